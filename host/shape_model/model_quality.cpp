#include "shape_model/model_quality.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "common/progress.hpp"
#include "common/random.hpp"

namespace meshparticles {

namespace {

// ShapeWorks' draws come from a stream of their own (seed ^ this), apart from ours.
constexpr std::uint64_t kShapeWorksStream = 0x5368617065576f72ull;

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

// `samples` shapes drawn from the first sds.size() modes, mode j's weight
// normal with standard deviation sds(j); of each, the mean point distance
// to the nearest training shape.
std::vector<double> drawn_distances(const ShapeModes& model, const std::vector<PointSet>& aligned,
                                    const Eigen::VectorXd& sds, std::size_t samples, SplitMix64& random) {
  std::vector<double> nearest;
  for (std::size_t k = 0; k < samples; ++k) {
    Eigen::VectorXd weights(sds.size());
    for (Eigen::Index j = 0; j < sds.size(); ++j) weights(j) = standard_normal(random) * sds(j);
    const PointSet drawn = model.shape(weights);
    double closest = std::numeric_limits<double>::infinity();
    for (const PointSet& shape : aligned) closest = std::min(closest, mean_point_distance(drawn, shape));
    nearest.push_back(closest);
  }
  return nearest;
}

// Each shape left out once, its model's first M modes rebuild it:
// errors[M - 1][shape] for M = 1 .. S - 1.
std::vector<std::vector<double>> leave_one_out_errors(const std::vector<PointSet>& aligned, ProgressLine& progress) {
  const std::size_t count = aligned.size();
  std::vector<std::vector<double>> errors(count - 1);
  for (std::size_t out = 0; out < count; ++out) {
    std::vector<PointSet> others;
    for (std::size_t s = 0; s < count; ++s) {
      if (s != out) others.push_back(aligned[s]);
    }
    const ShapeModes without = principal_modes(others);
    const Eigen::VectorXd offset = flattened(aligned[out]) - without.mean;
    for (std::size_t m = 1; m < count; ++m) {
      // Past the modes a smaller model has, the rebuild stays at its best.
      const auto used = Eigen::Index(std::min<std::size_t>(m, std::size_t(without.variances.size())));
      const Eigen::VectorXd weights = without.modes.leftCols(used).transpose() * offset;
      errors[m - 1].push_back(mean_point_distance(aligned[out], without.shape(weights)));
    }
    progress.update(out + 1, "generalization");
  }
  return errors;
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
  const bool as_shapeworks = modes > 0;
  ProgressLine progress("model measures", count + modes + (as_shapeworks ? count - 1 : 0), quiet);
  if (count >= 3) {
    const std::vector<std::vector<double>> errors = leave_one_out_errors(aligned, progress);
    for (std::size_t m = 1; m <= count - 2; ++m) quality.generalization.push_back(summary(errors[m - 1]));
    if (as_shapeworks) {
      for (const auto& per_shape : errors) quality.shapeworks.generalization.push_back(summary(per_shape).mean);
    }
  }

  SplitMix64 random(seed);
  for (std::size_t m = 1; m <= modes; ++m) {
    const Eigen::VectorXd sds = model.variances.head(Eigen::Index(m)).cwiseSqrt();
    quality.specificity.push_back(summary(drawn_distances(model, aligned, sds, samples, random)));
    progress.update(count + m, "specificity");
  }

  if (as_shapeworks) {
    // The singular values of the centred data matrix (shapes as columns):
    // sqrt((S - 1) variance); ShapeWorks draws each weight with one as its
    // variance. Modes past ours hold no variance: they add nothing.
    const Eigen::VectorXd singular = (double(count - 1) * model.variances).cwiseSqrt();
    SplitMix64 shapeworks_random(seed ^ kShapeWorksStream);
    for (std::size_t m = 1; m < count; ++m) {
      const auto used = Eigen::Index(std::min(m, modes));
      quality.shapeworks.compactness.push_back(quality.compactness[std::size_t(used) - 1]);
      const Eigen::VectorXd sds = singular.head(used).cwiseSqrt();
      quality.shapeworks.specificity.push_back(
          summary(drawn_distances(model, aligned, sds, ShapeWorksMeasures::kSamples, shapeworks_random)).mean);
      progress.update(count + modes + m, "specificity as ShapeWorks draws");
    }
  }
  progress.finish();
  return quality;
}

}  // namespace meshparticles
