// The shape model (host/shape_model) on populations whose answer is known:
// one shape in random poses (Procrustes must undo them exactly), and a
// shape plus known multiples of one displacement (PCA must find that one
// mode with that variance, and a model of it must rebuild left-out shapes);
// and shapes moved along known directions, whose measures as ShapeWorks
// computes them follow by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/random.hpp"
#include "shape_model/model_quality.hpp"
#include "shape_model/procrustes.hpp"
#include "shape_model/shape_modes.hpp"

namespace meshparticles::testing {
namespace {

PointSet random_points(std::size_t count, std::uint64_t seed) {
  SplitMix64 random(seed);
  PointSet points(Eigen::Index(count), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    points.row(i) << random.uniform() * 2 - 1, random.uniform() - 0.5, random.uniform() * 0.6 - 0.3;
  }
  return points;
}

// A random proper rotation (a unit quaternion), size and offset.
Similarity random_pose(SplitMix64& random) {
  Eigen::Quaterniond q(random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5);
  Similarity pose;
  pose.rotation = q.normalized().toRotationMatrix();
  pose.scale = 0.2 + 5 * random.uniform();
  pose.translation << 100 * random.uniform(), -50 * random.uniform(), 10 * random.uniform();
  return pose;
}

TEST(Procrustes, UndoesRandomPosesExactly) {
  const PointSet base = random_points(60, 7);
  SplitMix64 random(3);
  std::vector<PointSet> shapes;
  for (int s = 0; s < 8; ++s) shapes.push_back(random_pose(random).apply(base));
  const ProcrustesAlignment alignment = align_procrustes(shapes);
  EXPECT_TRUE(alignment.converged);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    EXPECT_LT((alignment.aligned[s] - alignment.aligned[0]).cwiseAbs().maxCoeff(), 1e-9 * alignment.mean_size) << s;
    // The recorded transform is the one that was applied.
    EXPECT_LT((alignment.transforms[s].apply(shapes[s]) - alignment.aligned[s]).cwiseAbs().maxCoeff(), 1e-12) << s;
    EXPECT_NEAR(alignment.transforms[s].rotation.determinant(), 1.0, 1e-12);
    EXPECT_NEAR((alignment.aligned[s].rowwise() - alignment.aligned[s].colwise().mean()).norm(), alignment.mean_size,
                1e-9 * alignment.mean_size);
  }
}

TEST(Procrustes, NeverMirrorsAShape) {
  const PointSet base = random_points(40, 11);
  PointSet mirrored = base;
  mirrored.col(0) *= -1;
  const ProcrustesAlignment alignment = align_procrustes({base, mirrored});
  for (const Similarity& t : alignment.transforms) EXPECT_NEAR(t.rotation.determinant(), 1.0, 1e-12);
  // A chiral shape and its mirror image stay apart.
  EXPECT_GT((alignment.aligned[0] - alignment.aligned[1]).rowwise().norm().mean(), 0.05 * alignment.mean_size);
}

TEST(Procrustes, WithoutScalingSizesAreKept) {
  const PointSet base = random_points(30, 5);
  SplitMix64 random(9);
  std::vector<PointSet> shapes;
  for (int s = 0; s < 4; ++s) {
    Similarity pose = random_pose(random);
    pose.scale = 1 + s;  // four sizes
    shapes.push_back(pose.apply(base));
  }
  const ProcrustesAlignment alignment = align_procrustes(shapes, /*with_scale=*/false);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    EXPECT_DOUBLE_EQ(alignment.transforms[s].scale, 1.0);
    const double size = (shapes[s].rowwise() - shapes[s].colwise().mean()).norm();
    EXPECT_NEAR((alignment.aligned[s].rowwise() - alignment.aligned[s].colwise().mean()).norm(), size, 1e-9 * size);
  }
}

// base + a_k * displacement, each in a random pose; a_k known. The
// displacement is a stretch along x: no rotation or translation can undo
// any of it (it is symmetric and centred), so the mode is all of it.
struct OneModePopulation {
  std::vector<PointSet> shapes;
  std::vector<double> amounts;
  std::vector<Similarity> poses;
  PointSet displacement;
};
OneModePopulation one_mode_population(std::size_t count) {
  OneModePopulation population;
  const PointSet base = random_points(80, 21);
  population.displacement = PointSet::Zero(base.rows(), 3);
  population.displacement.col(0) = base.col(0).array() - base.col(0).mean();
  SplitMix64 random(4);
  for (std::size_t s = 0; s < count; ++s) {
    const double amount = 0.4 * (random.uniform() - 0.5);
    population.amounts.push_back(amount);
    Similarity pose = random_pose(random);
    pose.scale = 1;  // without scaling, so the variance is known exactly
    population.poses.push_back(pose);
    population.shapes.push_back(pose.apply(base + amount * population.displacement));
  }
  return population;
}

TEST(ShapeModes, FindTheOneModeOfAPopulationWithItsVariance) {
  const OneModePopulation population = one_mode_population(10);
  const ProcrustesAlignment alignment = align_procrustes(population.shapes, /*with_scale=*/false);
  const ShapeModes model = principal_modes(alignment.aligned);
  ASSERT_GE(model.variances.size(), 1);
  double mean = 0, variance = 0;
  for (const double a : population.amounts) mean += a / double(population.amounts.size());
  for (const double a : population.amounts) variance += (a - mean) * (a - mean) / double(population.amounts.size() - 1);
  const double expected = variance * population.displacement.squaredNorm();
  EXPECT_NEAR(model.variances(0), expected, 0.01 * expected);
  EXPECT_GT(model.variances(0), 0.999 * model.total_variance());
  // The common frame is the first shape's pose, aligned: the stretch seen there.
  const Eigen::Matrix3d to_frame = alignment.transforms[0].rotation * population.poses[0].rotation;
  const Eigen::VectorXd direction =
      flattened((population.displacement * to_frame.transpose()).eval()).normalized();
  EXPECT_GT(std::abs(model.modes.col(0).dot(direction)), 0.999);
  EXPECT_NEAR(model.modes.col(0).norm(), 1.0, 1e-12);
}

TEST(ModelQuality, AOneModeModelRebuildsLeftOutShapesAndDrawsNearThem) {
  const OneModePopulation population = one_mode_population(10);
  const ProcrustesAlignment alignment = align_procrustes(population.shapes, /*with_scale=*/false);
  const ShapeModes model = principal_modes(alignment.aligned);
  const ModelQuality quality = measure_model(alignment.aligned, model, 200, 1);
  ASSERT_EQ(quality.compactness.size(), std::size_t(model.variances.size()));
  ASSERT_EQ(quality.generalization.size(), 8u);  // 1 .. S - 2
  EXPECT_GT(quality.compactness[0], 0.99);
  EXPECT_DOUBLE_EQ(quality.compactness.back(), 1.0);
  // The spread of the population, for scale: a mean point distance between shapes.
  const double spread = mean_point_distance(alignment.aligned[0], alignment.aligned[1]);
  EXPECT_LT(quality.generalization[0].mean, 0.1 * spread);
  EXPECT_LT(quality.specificity[0].mean, 0.5 * spread);
  // More modes never rebuild worse.
  for (std::size_t m = 1; m < quality.generalization.size(); ++m) {
    EXPECT_LE(quality.generalization[m].mean, quality.generalization[m - 1].mean + 1e-12);
  }
}

TEST(ModelQuality, TheSameInputsAndSeedGiveTheSameBits) {
  const OneModePopulation population = one_mode_population(6);
  const auto measure = [&](std::uint64_t seed) {
    const ProcrustesAlignment alignment = align_procrustes(population.shapes);
    return measure_model(alignment.aligned, principal_modes(alignment.aligned), 50, seed);
  };
  const ModelQuality a = measure(1), b = measure(1), c = measure(2);
  for (std::size_t m = 0; m < a.specificity.size(); ++m) {
    EXPECT_EQ(a.specificity[m].mean, b.specificity[m].mean);
    EXPECT_EQ(a.generalization.empty() ? 0.0 : a.generalization[0].mean,
              b.generalization.empty() ? 0.0 : b.generalization[0].mean);
  }
  EXPECT_NE(a.specificity[0].mean, c.specificity[0].mean);
}

// Shapes measured directly (as if aligned): the base plus a_k of one
// displacement and b_k of another. Each displacement moves point i by w_i
// (1 or 3, alternately), along x for the first and y for the second, so the
// two are orthogonal and equally long, and a shape at coefficients (a, b)
// lies |(a, b) - (a', b')| * mean(w) from one at (a', b'), point by point.
std::vector<PointSet> moved_shapes(const std::vector<Eigen::Vector2d>& coefficients) {
  const PointSet base = random_points(8, 13);
  std::vector<PointSet> shapes;
  for (const Eigen::Vector2d& c : coefficients) {
    PointSet shape = base;
    for (Eigen::Index i = 0; i < shape.rows(); ++i) {
      const double w = i % 2 == 0 ? 1.0 : 3.0;
      shape(i, 0) += w * c.x();
      shape(i, 1) += w * c.y();
    }
    shapes.push_back(shape);
  }
  return shapes;
}
constexpr double kMeanWeight = 2;       // mean of w over the points
constexpr double kSquaredWeights = 40;  // sum of w^2 over the 8 points: each displacement's squared length

TEST(ShapeWorksMeasures, CompactnessAndGeneralizationOfATriangleOfShapes) {
  // Coefficients (0, 0), (2, 0), (0, 2): centred, their scatter has
  // eigenvalues 4 and 4/3, so one mode holds 3/4. Left out, each shape is
  // rebuilt from the line through the other two: it is off by its distance
  // to that line, sqrt(2), 2 and 2, in coefficients.
  const std::vector<PointSet> shapes = moved_shapes({{0, 0}, {2, 0}, {0, 2}});
  const ShapeModes model = principal_modes(shapes);
  const ModelQuality quality = measure_model(shapes, model, 10, 1);
  const ShapeWorksMeasures& shapeworks = quality.shapeworks;
  ASSERT_EQ(shapeworks.compactness.size(), 2u);  // M = 1 .. S - 1
  EXPECT_NEAR(shapeworks.compactness[0], 0.75, 1e-12);
  EXPECT_NEAR(shapeworks.compactness[1], 1.0, 1e-12);
  const double expected = kMeanWeight * (std::sqrt(2.0) + 2 + 2) / 3;
  ASSERT_EQ(shapeworks.generalization.size(), 2u);
  EXPECT_NEAR(shapeworks.generalization[0], expected, 1e-12);
  // A model of two shapes has one mode: M = 2 rebuilds as M = 1 does.
  EXPECT_NEAR(shapeworks.generalization[1], expected, 1e-12);
  ASSERT_EQ(quality.generalization.size(), 1u);  // ours: M = 1 .. S - 2
  EXPECT_NEAR(quality.generalization[0].mean, expected, 1e-12);
}

// E| |X| - h | for X normal with standard deviation s (trapezoids over
// [0, h + 12 s]): the mean distance, in coefficients, of a drawn shape to
// the nearer of two shapes at -h and +h.
double expected_nearest(double s, double h) {
  const int steps = 200000;
  const double end = h + 12 * s, step = end / steps;
  double sum = 0;
  for (int k = 0; k <= steps; ++k) {
    const double x = k * step;
    const double f = std::abs(x - h) * 2 * std::exp(-x * x / (2 * s * s)) / (s * std::sqrt(2 * std::numbers::pi));
    sum += (k == 0 || k == steps ? 0.5 : 1.0) * f;
  }
  return sum * step;
}

TEST(ShapeWorksMeasures, SpecificityDrawsWithTheSingularValueAsVariance) {
  // Two shapes at a = -h and +h: one mode of variance 2 h^2 |D|^2 (S - 1 = 1),
  // singular value sigma = h sqrt(2 |D|^2). Ours draws the mode's weight with
  // that variance; ShapeWorks with sigma as its variance. In coefficients a
  // drawn shape is normal with sd sqrt(variance / |D|^2).
  const double h = 0.3;
  const std::vector<PointSet> shapes = moved_shapes({{-h, 0}, {h, 0}});
  const ShapeModes model = principal_modes(shapes);
  ASSERT_EQ(model.variances.size(), 1);
  const double variance = 2 * h * h * kSquaredWeights;
  EXPECT_NEAR(model.variances(0), variance, 1e-12 * variance);
  const ModelQuality quality = measure_model(shapes, model, ShapeWorksMeasures::kSamples, 7);
  const double ours = kMeanWeight * expected_nearest(std::sqrt(variance / kSquaredWeights), h);
  const double shapeworks = kMeanWeight * expected_nearest(std::sqrt(std::sqrt(variance) / kSquaredWeights), h);
  ASSERT_GT(ours / shapeworks, 1.2);  // the two conventions apart, well beyond the draws' noise
  // 1,000 draws: a standard error of about 2%.
  ASSERT_EQ(quality.specificity.size(), 1u);
  EXPECT_NEAR(quality.specificity[0].mean, ours, 0.06 * ours);
  ASSERT_EQ(quality.shapeworks.specificity.size(), 1u);
  EXPECT_NEAR(quality.shapeworks.specificity[0], shapeworks, 0.06 * shapeworks);
}

TEST(ShapeWorksMeasures, SeededApartFromOurs) {
  const std::vector<PointSet> shapes = moved_shapes({{0, 0}, {2, 0}, {0, 2}, {1, 1.5}});
  const ShapeModes model = principal_modes(shapes);
  const ModelQuality a = measure_model(shapes, model, 50, 3), b = measure_model(shapes, model, 80, 3),
                     c = measure_model(shapes, model, 50, 4);
  ASSERT_EQ(a.shapeworks.specificity.size(), 3u);
  // The same seed, whatever --samples: the same bits.
  EXPECT_EQ(a.shapeworks.specificity, b.shapeworks.specificity);
  EXPECT_NE(a.shapeworks.specificity, c.shapeworks.specificity);
}

TEST(ShapeWorksMeasures, NoneForShapesThatAreOneShape) {
  const std::vector<PointSet> shapes = moved_shapes({{1, 1}, {1, 1}, {1, 1}});
  const ModelQuality quality = measure_model(shapes, principal_modes(shapes), 10, 1);
  EXPECT_TRUE(quality.shapeworks.compactness.empty());
  EXPECT_TRUE(quality.shapeworks.generalization.empty());
  EXPECT_TRUE(quality.shapeworks.specificity.empty());
}

}  // namespace
}  // namespace meshparticles::testing
