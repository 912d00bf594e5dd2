#include "correspondence/ensemble_entropy.hpp"

#include <cmath>

#include "shape_model/procrustes.hpp"

namespace meshparticles {

namespace {

// The ensemble entropy's regulariser, per particle, in spacings: variation
// that moves particles by much less than this between shapes is shrunk
// (noise, a correspondence slipping), by much more is kept (a mode). At a
// tenth of a spacing, the part of a nonlinear mode that the linear modes
// miss (a bump growing) was shrunk too, pulling particles down the bump's
// sides: holes at its tip (cover 1.56 at n = 1,024).
constexpr double kShapeNoise = 0.05;
// How much of the shrinkable variation one step removes.
constexpr double kShrinkRate = 0.5;

}  // namespace

// With Y the centred aligned shapes as columns, (Y Y^T / S + alpha I)^-1 y_k
// = Y (Y^T Y / S + alpha I)^-1 e_k (S x S, ShapeWorks' dual form). Along a
// mode of variance lambda a shape moves back by rate alpha / (lambda +
// alpha) of its part. The spacing in the aligned frame is each shape's
// spacing at the aligned size, averaged.
CorrespondenceSteps EnsembleEntropy::steps(const std::vector<PointSet>& shapes,
                                           const std::vector<double>& spacings) const {
  const ProcrustesAlignment alignment = align_procrustes(shapes, true);
  const Eigen::Index count = Eigen::Index(shapes.size());
  double aligned_spacing = 0;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    aligned_spacing += spacings[k] * alignment.transforms[k].scale / double(count);
  }
  const Eigen::Index length = shapes.front().rows() * 3;
  Eigen::MatrixXd centred(length, count);
  for (Eigen::Index k = 0; k < count; ++k) centred.col(k) = flattened(alignment.aligned[std::size_t(k)]);
  const Eigen::VectorXd mean = centred.rowwise().mean();
  centred.colwise() -= mean;
  const double particles = double(shapes.front().rows());
  const double alpha = particles * std::pow(kShapeNoise * aligned_spacing, 2);
  const Eigen::MatrixXd gram = centred.transpose() * centred / double(count) +
                               alpha * Eigen::MatrixXd::Identity(count, count);
  const Eigen::MatrixXd pulled = centred * gram.ldlt().solve(Eigen::MatrixXd::Identity(count, count));
  CorrespondenceSteps result;
  double total = 0;
  for (Eigen::Index k = 0; k < count; ++k) {
    const Similarity& to_common = alignment.transforms[std::size_t(k)];
    const PointSet aligned_step = unflattened(-kShrinkRate * alpha * pulled.col(k));
    total += aligned_step.rowwise().norm().mean();
    // Back into the shape's own coordinates: turned back, unscaled.
    result.steps.push_back(aligned_step * to_common.rotation / to_common.scale);
  }
  result.mean_length = total / double(count) / aligned_spacing;
  return result;
}

}  // namespace meshparticles
