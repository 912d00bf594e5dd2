#include "correspondence/closest_surface_point.hpp"

#include <limits>

#include "mesh/nearest_on_triangle.hpp"

namespace meshparticles {

namespace {

Vec3 as_vec3(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

SurfaceHit closest_surface_point(const SurfaceMesh& mesh, const VertexTriangles& around, const PointSet& points,
                                 const MatrixRowTree<PointSet>& tree, const Eigen::RowVector3d& query,
                                 std::size_t candidates) {
  SurfaceHit best;
  best.distance = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d p = query.transpose();
  for (const Eigen::Index v : tree.nearest(query, candidates)) {
    for (const std::uint32_t t : around.around(VertexId(v))) {
      const Triangle& corners = mesh.triangles()[t];
      const Eigen::Vector3d a = points.row(corners[0]).transpose(), b = points.row(corners[1]).transpose(),
                            c = points.row(corners[2]).transpose();
      const std::array<double, 3> weights = nearest_on_triangle(as_vec3(p), as_vec3(a), as_vec3(b), as_vec3(c));
      const Eigen::Vector3d at = weights[0] * a + weights[1] * b + weights[2] * c;
      const double distance = (at - p).norm();
      if (distance < best.distance) {
        best = {{t, weights, as_vec3(at)}, distance};
      }
    }
  }
  return best;
}

}  // namespace meshparticles
