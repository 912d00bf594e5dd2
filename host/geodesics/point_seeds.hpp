#pragma once
// Where a march from a point between vertices starts: its triangle's
// corners and the vertices of the triangles around them, each at its
// distance from the point along the straight line through the triangles
// between them unfolded into one plane.
//
// Started from the corners alone, fast marching misreads about one vertex
// in fifty by up to a tenth of a spacing, on a flat patch where every
// distance is a straight line: a vertex of a corner's fan whose update
// needs a farther fan vertex is accepted first, at its way through the
// corner, and its error spreads outward (from a vertex, one in three
// thousand). The fans' straight lines are exact there.
#include <cstdint>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

struct PointSeeds {
  std::vector<VertexId> vertices;  // the corners first, then the fans' vertices, each once
  std::vector<double> distances;   // parallel: the way from the point
};

// Fills `seeds` for `point` on `mesh` (`rings`: its triangles around each
// vertex). A fan vertex is seeded only where the straight line from the
// point crosses every edge between them within the edge, turning less than
// half a turn about the corner: a way along the surface, never shorter than
// the surface allows. Where an edge has more than two triangles, the
// unfolding stops there.
void point_seeds(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceLocation& point,
                 PointSeeds& seeds);

}  // namespace meshparticles
