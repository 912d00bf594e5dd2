#pragma once
// The modes of variation of aligned shapes: principal component analysis
// of their flat 3N vectors. With fewer shapes S than coordinates 3N (the
// usual case: tens of shapes, thousands of points), the eigenvectors come
// from the S x S Gram matrix (the "dual" covariance ShapeWorks uses), which
// gives the same nonzero variances and modes for far less work.
#include <vector>

#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

struct ShapeModes {
  Eigen::VectorXd mean;       // 3N
  Eigen::MatrixXd modes;      // 3N x K, orthonormal columns, largest variance first
  Eigen::VectorXd variances;  // K, descending, each above 1e-12 of their sum
  // Each mode's sign is chosen so that its largest component (by size, the
  // first of equals) is positive: the same population gives the same model.

  double total_variance() const { return variances.sum(); }
  // mean + modes(:, 0..k-1) * weights: a shape of the model.
  PointSet shape(const Eigen::VectorXd& weights) const;
};

// Of at least two aligned shapes of equal point counts; at most S - 1 modes.
ShapeModes principal_modes(const std::vector<PointSet>& aligned);

}  // namespace meshparticles
