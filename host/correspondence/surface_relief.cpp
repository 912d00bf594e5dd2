#include "correspondence/surface_relief.hpp"

#include <algorithm>
#include <cmath>

#include "correspondence/vertex_fields.hpp"

namespace meshparticles {

Eigen::VectorXd surface_relief(const SurfaceMesh& mesh, const PointSet& points) {
  const Eigen::Index count = points.rows();
  const PointSet normals = vertex_normals(mesh.triangles(), points);
  // One-ring averaging spreads like diffusion: after r rounds over edges of
  // length e, about sqrt(r / 2) e; e^2 is about 1.15 area / vertices (an
  // even mesh's), so r = 2 scale^2 vertices / 1.15 reaches kReliefScale of
  // sqrt(area) whatever the resolution. At most 400 rounds: past 90,000
  // vertices the reach narrows rather than the cost growing with the
  // square of the resolution.
  const int rounds =
      std::clamp(int(std::lround(2 * kReliefScale * kReliefScale * double(count) / 1.15)), 1, 400);
  PointSet smooth = points;
  smooth_over(mesh, smooth, rounds);
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

Eigen::VectorXd detrended_relief(const SurfaceMesh& mesh, const PointSet& points) {
  Eigen::VectorXd relief = surface_relief(mesh, points);
  if (signed_volume(mesh.triangles(), points) < 0) relief = -relief;
  PointSet trend = PointSet::Zero(relief.size(), 3);
  trend.col(0) = relief;
  const int rounds = std::clamp(int(std::lround(2 * kReliefBand * kReliefBand * double(relief.size()) / 1.15)), 1, 1600);
  smooth_over(mesh, trend, rounds);
  return relief - trend.col(0);
}

}  // namespace meshparticles
