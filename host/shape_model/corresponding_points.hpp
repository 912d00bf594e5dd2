#pragma once
// A shape as a statistical shape model sees it: N corresponding points,
// point i at the same place on every shape of the population (the rows of
// ShapeWorks' .particles files), and the flat 3N vector PCA works on.
#include <Eigen/Dense>

namespace meshparticles {

using PointSet = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // one row per point

// x0, y0, z0, x1, ... and back.
inline Eigen::VectorXd flattened(const PointSet& points) {
  Eigen::VectorXd flat(points.rows() * 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) flat.segment<3>(3 * i) = points.row(i).transpose();
  return flat;
}
inline PointSet unflattened(const Eigen::VectorXd& flat) {
  PointSet points(flat.size() / 3, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) points.row(i) = flat.segment<3>(3 * i).transpose();
  return points;
}

// The mean distance between corresponding points: the yardstick of every
// model measure (in the units of the points).
inline double mean_point_distance(const PointSet& a, const PointSet& b) {
  return (a - b).rowwise().norm().mean();
}

}  // namespace meshparticles
