#pragma once
// Generalized Procrustes analysis: each shape moved (and scaled, unless
// asked not to) onto the population's mean, so that what is left between
// shapes is shape, not pose. Shapes arrive in any position, orientation
// and size; each gets the similarity that takes it into the common frame.
#include <cstddef>
#include <vector>

#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// aligned = scale * rotation * world + translation (points as columns).
struct Similarity {
  double scale = 1;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // proper: determinant +1
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  PointSet apply(const PointSet& world) const;
  Eigen::Matrix4d matrix() const;  // homogeneous, for files
};

struct ProcrustesAlignment {
  std::vector<PointSet> aligned;       // per shape, in the common frame
  std::vector<Similarity> transforms;  // per shape, world -> common frame
  std::size_t iterations = 0;
  bool converged = false;
  // The common frame's unit: the mean centroid size of the input shapes
  // (with scaling every aligned shape has this size), so aligned
  // coordinates read in the inputs' units.
  double mean_size = 0;
};

// The proper rotation R minimising |points * R^T - target| over centred
// corresponding rows (Kabsch): never a reflection.
Eigen::Matrix3d best_rotation(const PointSet& points, const PointSet& target);

// Shapes of equal point counts, at least 2 points each and no shape with
// all its points at one place (callers check: UserError is theirs to word).
// The first shape fixes the frame's orientation; the result depends only on
// the inputs (deterministic). Stops when the mean moves by less than 1e-12
// of its size, or after 100 rounds.
ProcrustesAlignment align_procrustes(const std::vector<PointSet>& shapes, bool with_scale = true);

}  // namespace meshparticles
