#include "shape_model/procrustes.hpp"

#include <cmath>

namespace meshparticles {

namespace {

constexpr std::size_t kMaxRounds = 100;
constexpr double kTolerance = 1e-12;

Eigen::RowVector3d centroid(const PointSet& points) { return points.colwise().mean(); }

}  // namespace

Eigen::Matrix3d best_rotation(const PointSet& points, const PointSet& target) {
  const Eigen::Matrix3d covariance = target.transpose() * points;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
  fix(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixU() * fix * svd.matrixV().transpose();
}

PointSet Similarity::apply(const PointSet& world) const {
  PointSet moved = (scale * (world * rotation.transpose())).eval();
  moved.rowwise() += translation.transpose();
  return moved;
}

Eigen::Matrix4d Similarity::matrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = scale * rotation;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

ProcrustesAlignment align_procrustes(const std::vector<PointSet>& shapes, bool with_scale) {
  ProcrustesAlignment result;
  const std::size_t count = shapes.size();
  std::vector<PointSet> centred(count);
  std::vector<Eigen::RowVector3d> centroids(count);
  std::vector<double> sizes(count);
  for (std::size_t s = 0; s < count; ++s) {
    centroids[s] = centroid(shapes[s]);
    centred[s] = shapes[s].rowwise() - centroids[s];
    sizes[s] = centred[s].norm();  // centroid size
    result.mean_size += sizes[s] / double(count);
  }
  // In the common frame every shape has size mean_size (with scaling).
  std::vector<double> scales(count, 1.0);
  if (with_scale) {
    for (std::size_t s = 0; s < count; ++s) scales[s] = result.mean_size / sizes[s];
  }
  std::vector<Eigen::Matrix3d> rotations(count, Eigen::Matrix3d::Identity());
  PointSet mean = scales[0] * centred[0];
  for (result.iterations = 1; result.iterations <= kMaxRounds; ++result.iterations) {
    PointSet next = PointSet::Zero(mean.rows(), 3);
    for (std::size_t s = 0; s < count; ++s) {
      rotations[s] = best_rotation(centred[s], mean);
      next += scales[s] * centred[s] * rotations[s].transpose();
    }
    next /= double(count);
    // Keep the frame: the new mean turned back onto the old one, and at the
    // common size, so the rounds cannot drift or shrink.
    next = (next * best_rotation(next, mean).transpose()).eval();
    if (with_scale) next *= result.mean_size / next.norm();
    const double change = (next - mean).norm();
    mean = next;
    if (change <= kTolerance * result.mean_size) {
      result.converged = true;
      break;
    }
  }
  result.iterations = std::min(result.iterations, kMaxRounds);
  for (std::size_t s = 0; s < count; ++s) {
    rotations[s] = best_rotation(centred[s], mean);
    Similarity transform;
    transform.scale = scales[s];
    transform.rotation = rotations[s];
    transform.translation = -(scales[s] * (rotations[s] * centroids[s].transpose()));
    result.transforms.push_back(transform);
    result.aligned.push_back(transform.apply(shapes[s]));
  }
  return result;
}

}  // namespace meshparticles
