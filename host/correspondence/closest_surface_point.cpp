#include "correspondence/closest_surface_point.hpp"

#include <limits>

namespace meshparticles {

namespace {

// Barycentric weights of the point of triangle abc nearest to p (Ericson,
// Real-Time Collision Detection, 5.1.5: by the Voronoi regions of the
// corners, then the edges, then the face).
std::array<double, 3> nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0)) return {1, 0, 0};  // a degenerate triangle: its first corner
  const double v = vb / denominator, w = vc / denominator;
  return {1 - v - w, v, w};
}

}  // namespace

SurfaceHit closest_surface_point(const SurfaceMesh& mesh, const VertexTriangles& around, const PointSet& points,
                                 const PointTree& tree, const Eigen::RowVector3d& query, std::size_t candidates) {
  SurfaceHit best;
  best.distance = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d p = query.transpose();
  for (const Eigen::Index v : tree.nearest(query, candidates)) {
    for (const std::uint32_t t : around.around(VertexId(v))) {
      const Triangle& corners = mesh.triangles()[t];
      const Eigen::Vector3d a = points.row(corners[0]).transpose(), b = points.row(corners[1]).transpose(),
                            c = points.row(corners[2]).transpose();
      const std::array<double, 3> weights = nearest_on_triangle(p, a, b, c);
      const Eigen::Vector3d at = weights[0] * a + weights[1] * b + weights[2] * c;
      const double distance = (at - p).norm();
      if (distance < best.distance) {
        best = {corners, weights, at.transpose(), distance};
      }
    }
  }
  return best;
}

}  // namespace meshparticles
