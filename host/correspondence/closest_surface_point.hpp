#pragma once
// The point of a mesh's surface nearest to a point in space: a triangle and
// barycentric weights, found among the triangles around the query's nearest
// vertices (on a mesh of well-shaped triangles the nearest point lies in
// one of them).
#include "mesh/point_cloud_tree.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"
#include "shape_model/point_sets.hpp"

namespace meshparticles {

struct SurfaceHit {
  SurfaceLocation location;  // `at` in the coordinates of `points`
  double distance = 0;
};

// The nearest point to `query` on the triangles around its `candidates`
// nearest vertices; `points` are the mesh's vertices in the query's frame
// and `tree` their k-d tree. Ties: the first triangle met.
SurfaceHit closest_surface_point(const SurfaceMesh& mesh, const VertexTriangles& around, const PointSet& points,
                                 const MatrixRowTree<PointSet>& tree, const Eigen::RowVector3d& query,
                                 std::size_t candidates = 8);

}  // namespace meshparticles
