#pragma once
// The widest hole a set of points leaves in a surface: the point of the
// surface farthest from them along it, between the vertices too.
//
// The diagram at the vertices (particles/surface_voronoi) misses the holes
// between them: at n = 1,024 a FAUST person of 5,000 vertices has 2 to 5
// of them a particle, and `quality`, which measures on a finer mesh, found
// holes a fifth of a spacing wider than the vertices showed. Nor does a
// straight line do (particles/hole_pull): across a finger thinner than a
// spacing it is far shorter than the way round.
#include <algorithm>
#include <cstdint>
#include <span>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"
#include "particles/surface_voronoi.hpp"

namespace meshparticles {

struct WidestHole {
  SurfaceLocation at;
  std::uint32_t owner = SurfaceVoronoi::kNoPoint;  // the diagram's point nearest it
  double away = 0;                                 // how far, along the surface
};

// `diagram` is that of `points`, `rings` the triangles around each of
// `mesh`'s vertices (mesh/vertex_triangles; SurfaceWalk holds them). Sampled at each triangle's points about
// `step` apart (a barycentric grid, corners and edges too). A point's
// distance is the least of: fast marching's update from two corners one
// point holds (its source unfolded into the triangle's plane,
// geodesics/point_source_update); for each vertex of the corners' rings,
// the straight line to its point stretched as that point's way to the
// vertex is (exact on a plane, more round a finger), within what the
// vertex's distance bounds; the straight line to each point in the
// triangles around the corners (which may hold no vertex at all). A
// corner's distance plus the straight way from it would count a hole where
// three regions meet up to a third of an edge too wide. Only the triangles
// whose corners leave room for a point farther than the farthest found so
// far are sampled: a few around each hole. Ties go to the first triangle,
// then its first point; a diagram of no points has none (away 0).
WidestHole widest_hole(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceVoronoi& diagram,
                       std::span<const SurfaceLocation> points, double step);

// How wide a hole is taken to be: `hole`'s width, or the diagram's at the
// vertices where that reads wider (straight lines stretched less the
// marching's excess read a curved part's holes short: FAUST's poses with
// their arms overhead went to cover 1.17x their own run's at n = 512).
inline double hole_width(const WidestHole& hole, const SurfaceVoronoi& diagram) {
  return std::max(hole.away, diagram.cover());
}

}  // namespace meshparticles
