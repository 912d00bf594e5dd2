#include "correspondence/surface_relief.hpp"

#include <algorithm>
#include <cmath>

namespace meshparticles {

Eigen::VectorXd surface_relief(const SurfaceMesh& mesh, const PointSet& points) {
  const Eigen::Index count = points.rows();
  double area = 0;
  PointSet normals = PointSet::Zero(count, 3);
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::RowVector3d a = points.row(Eigen::Index(t[0]));
    const Eigen::RowVector3d n = (points.row(Eigen::Index(t[1])) - a).cross(points.row(Eigen::Index(t[2])) - a);
    area += 0.5 * n.norm();
    for (const VertexId v : t) normals.row(Eigen::Index(v)) += n;
  }
  normals.rowwise().normalize();
  // One-ring averaging spreads like diffusion: after r rounds over edges of
  // length e, about sqrt(r / 2) e; e^2 is about 1.15 area / vertices (an
  // even mesh's), so the reach follows the area whatever the resolution.
  const double edge_squared = 1.15 * area / double(std::max<Eigen::Index>(count, 1));
  // At most 400 rounds: past 90,000 vertices the reach narrows rather than
  // the cost growing with the square of the resolution.
  const int rounds = std::clamp(int(std::lround(2 * kReliefScale * kReliefScale * area / edge_squared)), 1, 400);
  PointSet smooth = points;
  PointSet next(count, 3);
  for (int round = 0; round < rounds; ++round) {
    for (VertexId v = 0; v < VertexId(count); ++v) {
      Eigen::RowVector3d sum = smooth.row(Eigen::Index(v));
      for (const VertexId w : mesh.one_ring(v)) sum += smooth.row(Eigen::Index(w));
      next.row(Eigen::Index(v)) = sum / double(mesh.valence(v) + 1);
    }
    smooth.swap(next);
  }
  Eigen::VectorXd relief(count);
  for (Eigen::Index v = 0; v < count; ++v) relief(v) = (points.row(v) - smooth.row(v)).dot(normals.row(v));
  return relief;
}

double relief_agreement(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::vector<Eigen::Index>& pairs) {
  const Eigen::Index count = a.size();
  double ma = 0, mb = 0;
  for (Eigen::Index i = 0; i < count; ++i) {
    ma += a(i);
    mb += b(pairs[std::size_t(i)]);
  }
  ma /= double(count);
  mb /= double(count);
  double ab = 0, aa = 0, bb = 0;
  for (Eigen::Index i = 0; i < count; ++i) {
    const double x = a(i) - ma, y = b(pairs[std::size_t(i)]) - mb;
    ab += x * y;
    aa += x * x;
    bb += y * y;
  }
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0;
}

}  // namespace meshparticles
