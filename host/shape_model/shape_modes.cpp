#include "shape_model/shape_modes.hpp"

#include <cmath>

namespace meshparticles {

namespace {

constexpr double kNegligible = 1e-12;  // of the total variance
// A variance under this share of the mean shape's squared size is rounding
// (shapes equal but for the last bits: three copies of one file gave "one
// mode holding 100%"), not a mode.
constexpr double kRounding = 1e-20;

}  // namespace

PointSet ShapeModes::shape(const Eigen::VectorXd& weights) const {
  return unflattened(mean + modes.leftCols(weights.size()) * weights);
}

ShapeModes principal_modes(const std::vector<PointSet>& aligned) {
  const auto count = Eigen::Index(aligned.size());
  Eigen::MatrixXd data(count, aligned.front().rows() * 3);  // a shape per row
  for (Eigen::Index s = 0; s < count; ++s) data.row(s) = flattened(aligned[std::size_t(s)]).transpose();
  ShapeModes model;
  model.mean = data.colwise().mean().transpose();
  const Eigen::MatrixXd centred = data.rowwise() - model.mean.transpose();
  const Eigen::MatrixXd gram = centred * centred.transpose() / double(count - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(gram);
  const Eigen::VectorXd values = solver.eigenvalues();  // ascending
  const double total = std::max(values.sum(), 0.0);
  const double least = std::max(kNegligible * total, kRounding * model.mean.squaredNorm());
  std::vector<Eigen::Index> kept;
  for (Eigen::Index k = count - 1; k >= 0; --k) {
    if (values(k) > least) kept.push_back(k);
  }
  model.modes.resize(centred.cols(), Eigen::Index(kept.size()));
  model.variances.resize(Eigen::Index(kept.size()));
  for (std::size_t j = 0; j < kept.size(); ++j) {
    Eigen::VectorXd mode = centred.transpose() * solver.eigenvectors().col(kept[j]);
    mode.normalize();
    Eigen::Index largest = 0;
    for (Eigen::Index i = 1; i < mode.size(); ++i) {
      if (std::abs(mode(i)) > std::abs(mode(largest))) largest = i;
    }
    if (mode(largest) < 0) mode = -mode;
    model.modes.col(Eigen::Index(j)) = mode;
    model.variances(Eigen::Index(j)) = values(kept[j]);
  }
  return model;
}

}  // namespace meshparticles
