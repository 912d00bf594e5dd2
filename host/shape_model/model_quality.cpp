#include "shape_model/model_quality.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "common/progress.hpp"
#include "common/random.hpp"

namespace meshparticles {

namespace {

ModelMeasure summary(const std::vector<double>& values) {
  ModelMeasure measure;
  for (const double v : values) measure.mean += v / double(values.size());
  for (const double v : values) measure.sd += (v - measure.mean) * (v - measure.mean);
  measure.sd = values.size() > 1 ? std::sqrt(measure.sd / double(values.size() - 1)) : 0.0;
  return measure;
}

// A standard normal number (Box-Muller), from SplitMix64 so every platform
// draws the same shapes.
double standard_normal(SplitMix64& random) {
  const double u = 1.0 - random.uniform();  // (0, 1]
  const double v = random.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

}  // namespace

ModelQuality measure_model(const std::vector<PointSet>& aligned, const ShapeModes& model, std::size_t samples,
                           std::uint64_t seed, bool quiet) {
  ModelQuality quality;
  quality.samples = samples;
  const auto modes = std::size_t(model.variances.size());
  double held = 0;
  for (std::size_t m = 0; m < modes; ++m) {
    held += model.variances(Eigen::Index(m));
    quality.compactness.push_back(held / model.total_variance());
  }

  const std::size_t count = aligned.size();
  ProgressLine progress("model measures", count + modes, quiet);
  if (count >= 3) {
    // Each shape left out once; its model's modes rebuild it.
    std::vector<std::vector<double>> errors(count - 2);
    for (std::size_t out = 0; out < count; ++out) {
      std::vector<PointSet> others;
      for (std::size_t s = 0; s < count; ++s) {
        if (s != out) others.push_back(aligned[s]);
      }
      const ShapeModes without = principal_modes(others);
      const Eigen::VectorXd offset = flattened(aligned[out]) - without.mean;
      for (std::size_t m = 1; m <= count - 2; ++m) {
        // Past the modes a smaller model has, the rebuild stays at its best.
        const auto used = Eigen::Index(std::min<std::size_t>(m, std::size_t(without.variances.size())));
        const Eigen::VectorXd weights = without.modes.leftCols(used).transpose() * offset;
        errors[m - 1].push_back(mean_point_distance(aligned[out], without.shape(weights)));
      }
      progress.update(out + 1, "generalization");
    }
    for (const auto& per_shape : errors) quality.generalization.push_back(summary(per_shape));
  }

  SplitMix64 random(seed);
  for (std::size_t m = 1; m <= modes; ++m) {
    std::vector<double> nearest;
    for (std::size_t k = 0; k < samples; ++k) {
      Eigen::VectorXd weights = Eigen::VectorXd::Zero(Eigen::Index(m));
      for (Eigen::Index j = 0; j < Eigen::Index(m); ++j) {
        weights(j) = standard_normal(random) * std::sqrt(model.variances(j));
      }
      const PointSet drawn = model.shape(weights);
      double closest = std::numeric_limits<double>::infinity();
      for (const PointSet& shape : aligned) closest = std::min(closest, mean_point_distance(drawn, shape));
      nearest.push_back(closest);
    }
    quality.specificity.push_back(summary(nearest));
    progress.update(count + m, "specificity");
  }
  progress.finish();
  return quality;
}

}  // namespace meshparticles
