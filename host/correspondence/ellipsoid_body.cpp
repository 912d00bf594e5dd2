#include "correspondence/ellipsoid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common/median.hpp"

namespace meshparticles {

namespace {

constexpr int kFitRounds = 10;
constexpr double kKeptSpread = 3;     // vertices within this many robust deviations stay in the fit
constexpr double kMostlyOn = 0.01;    // the median distance off the quadric, over the vertices' rms radius
constexpr Eigen::Index kMaxPoints = 4000;

}  // namespace

std::optional<EllipsoidBody> ellipsoid_body(const PointSet& vertices) {
  if (vertices.rows() < 10) return std::nullopt;
  const Eigen::Index stride = std::max<Eigen::Index>(1, (vertices.rows() + kMaxPoints - 1) / kMaxPoints);
  const Eigen::Index count = (vertices.rows() + stride - 1) / stride;
  const Eigen::RowVector3d mean = vertices.colwise().mean();
  PointSet x(count, 3);
  for (Eigen::Index i = 0; i < count; ++i) x.row(i) = vertices.row(i * stride) - mean;
  const double size = std::sqrt(x.rowwise().squaredNorm().mean());
  if (!(size > 0)) return std::nullopt;
  x /= size;
  // Each vertex's row of the quadric x'Mx + 2b'x + c = 0 (M symmetric).
  Eigen::MatrixXd rows(count, 10);
  for (Eigen::Index i = 0; i < count; ++i) {
    const double a = x(i, 0), b = x(i, 1), c = x(i, 2);
    rows.row(i) << a * a, b * b, c * c, 2 * a * b, 2 * a * c, 2 * b * c, 2 * a, 2 * b, 2 * c, 1;
  }
  Eigen::VectorXd kept = Eigen::VectorXd::Ones(count);
  Eigen::Matrix3d quadric;
  Eigen::Vector3d linear;
  double constant = 0, typical = 0;
  for (int round = 0; round < kFitRounds; ++round) {
    // The unit coefficients nearest a null vector of the kept rows.
    const Eigen::Matrix<double, 10, 10> normal = rows.transpose() * kept.asDiagonal() * rows;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 10, 10>> solver(normal);
    const Eigen::Matrix<double, 10, 1> q = solver.eigenvectors().col(0);
    quadric << q(0), q(3), q(4), q(3), q(1), q(5), q(4), q(5), q(2);
    linear << q(6), q(7), q(8);
    constant = q(9);
    // Each vertex's distance off it, to first order (the value over the gradient).
    std::vector<double> distances(std::size_t(count), 0.0);
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Vector3d p = x.row(i).transpose();
      const double value = rows.row(i).dot(q);
      const double gradient = (2 * (quadric * p + linear)).norm();
      distances[std::size_t(i)] = gradient > 0 ? std::abs(value) / gradient : std::numeric_limits<double>::infinity();
    }
    typical = median(distances);
    const double cutoff = kKeptSpread * 1.4826 * typical;
    for (Eigen::Index i = 0; i < count; ++i) kept(i) = distances[std::size_t(i)] <= cutoff ? 1.0 : 0.0;
  }
  if (quadric.trace() < 0) {
    quadric = -quadric;
    linear = -linear;
    constant = -constant;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> shape(quadric);
  if (!(typical < kMostlyOn) || !(shape.eigenvalues().minCoeff() > 0)) return std::nullopt;
  // (x - o)'M(x - o) = level, o = -M^-1 b.
  const Eigen::Vector3d origin = -(shape.eigenvectors() * (shape.eigenvalues().cwiseInverse().asDiagonal() *
                                                          (shape.eigenvectors().transpose() * linear)));
  const double level = origin.dot(quadric * origin) - constant;
  if (!(level > 0)) return std::nullopt;
  EllipsoidBody body;
  body.centre = mean.transpose() + size * origin;
  body.radii = size * (level / shape.eigenvalues().array()).sqrt();
  // The longest axis has the least eigenvalue.
  for (int k = 0; k < 3; ++k) body.axes.row(k) = shape.eigenvectors().col(k).transpose();
  if (body.axes.determinant() < 0) body.axes.row(2) *= -1;  // a proper turn
  return body;
}

PointSet EllipsoidBody::to_unit_sphere(const PointSet& points) const {
  return ((points.rowwise() - centre.transpose()) * axes.transpose()) * radii.cwiseInverse().asDiagonal();
}

}  // namespace meshparticles
