// correspondence/ensemble_entropy: the term's contract (correspondence_term):
// the same shapes give the same steps, bit for bit; the steps do not depend
// on the shapes' order, nor on how each shape is posed (a step is in its
// shape's own coordinates, turned and scaled with it); shapes that differ
// by a pose alone get no step; and a step shrinks the variation that one
// shape alone has.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "correspondence/ensemble_entropy.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles::testing {
namespace {

constexpr Eigen::Index kParticles = 60;

Eigen::Matrix3d turn(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

PointSet posed(const PointSet& points, const Eigen::Matrix3d& rotation, double scale, const Eigen::RowVector3d& offset) {
  return ((scale * points * rotation.transpose()).rowwise() + offset).eval();
}

// A unit sphere's points; each shape stretched along x by its own amount (a
// mode every shape shares), with noise of its own (what few shapes share),
// then posed.
struct Population {
  std::vector<PointSet> shapes;
  std::vector<double> spacings;
};
Population population(std::size_t count, double noise, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  PointSet sphere(kParticles, 3);
  for (Eigen::Index i = 0; i < kParticles; ++i) {
    sphere.row(i) << normal(random), normal(random), normal(random);
    sphere.row(i).normalize();
  }
  Population result;
  for (std::size_t k = 0; k < count; ++k) {
    PointSet shape = sphere;
    shape.col(0) *= 1 + 0.3 * double(k) / double(count);
    for (Eigen::Index i = 0; i < kParticles; ++i) {
      for (int c = 0; c < 3; ++c) shape(i, c) += noise * normal(random);
    }
    const double scale = 0.5 + double(k) * 0.4;
    result.shapes.push_back(posed(shape, turn(0.3 * double(k), 1.1 - 0.2 * double(k), 0.7), scale,
                                  Eigen::RowVector3d(double(k), -2.0, 0.5 * double(k))));
    result.spacings.push_back(0.4 * scale);
  }
  return result;
}

double largest(const PointSet& points) { return points.cwiseAbs().maxCoeff(); }

TEST(EnsembleEntropy, TheSameShapesGiveTheSameStepsBitForBit) {
  const Population shapes = population(5, 0.02, 1);
  const CorrespondenceSteps a = EnsembleEntropy().steps(shapes.shapes, shapes.spacings);
  const CorrespondenceSteps b = EnsembleEntropy().steps(shapes.shapes, shapes.spacings);
  ASSERT_EQ(a.steps.size(), 5u);
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    EXPECT_EQ(a.steps[k].rows(), kParticles);
    EXPECT_EQ(a.steps[k], b.steps[k]) << "shape " << k;
  }
  EXPECT_EQ(a.mean_length, b.mean_length);
  EXPECT_GT(a.mean_length, 0.0);
}

TEST(EnsembleEntropy, StepsDoNotDependOnTheShapesOrder) {
  const Population shapes = population(5, 0.02, 2);
  const CorrespondenceSteps forward = EnsembleEntropy().steps(shapes.shapes, shapes.spacings);
  const std::vector<std::size_t> order{3, 0, 4, 2, 1};
  Population shuffled;
  for (std::size_t k : order) {
    shuffled.shapes.push_back(shapes.shapes[k]);
    shuffled.spacings.push_back(shapes.spacings[k]);
  }
  const CorrespondenceSteps reordered = EnsembleEntropy().steps(shuffled.shapes, shuffled.spacings);
  for (std::size_t j = 0; j < order.size(); ++j) {
    const PointSet& expected = forward.steps[order[j]];
    EXPECT_LT(largest(reordered.steps[j] - expected), 1e-9 * largest(expected)) << "shape " << order[j];
  }
  EXPECT_NEAR(reordered.mean_length, forward.mean_length, 1e-9 * forward.mean_length);
}

// Shape 2 moved, turned and scaled: its step is the old one turned and
// scaled with it; every other shape's is the same.
TEST(EnsembleEntropy, AStepTurnsAndScalesWithItsShape) {
  const Population shapes = population(4, 0.02, 3);
  const CorrespondenceSteps before = EnsembleEntropy().steps(shapes.shapes, shapes.spacings);
  Population moved = shapes;
  const Eigen::Matrix3d rotation = turn(2.0, -0.4, 1.3);
  moved.shapes[2] = posed(shapes.shapes[2], rotation, 3.0, Eigen::RowVector3d(10, 20, -5));
  moved.spacings[2] *= 3.0;
  const CorrespondenceSteps after = EnsembleEntropy().steps(moved.shapes, moved.spacings);
  for (std::size_t k = 0; k < 4; ++k) {
    const PointSet expected = k == 2 ? PointSet(3.0 * before.steps[k] * rotation.transpose()) : before.steps[k];
    EXPECT_LT(largest(after.steps[k] - expected), 1e-8 * largest(expected)) << "shape " << k;
  }
}

TEST(EnsembleEntropy, ShapesThatDifferByAPoseAloneGetNoStep) {
  const Population one = population(1, 0.0, 4);
  std::vector<PointSet> shapes;
  std::vector<double> spacings;
  for (int k = 0; k < 4; ++k) {
    const double scale = 1.0 + 0.5 * k;
    shapes.push_back(posed(one.shapes.front(), turn(k, 0.5 * k, -k), scale, Eigen::RowVector3d(k, k, -k)));
    spacings.push_back(0.4 * scale);
  }
  const CorrespondenceSteps steps = EnsembleEntropy().steps(shapes, spacings);
  for (std::size_t k = 0; k < shapes.size(); ++k) EXPECT_LT(largest(steps.steps[k]), 1e-9) << "shape " << k;
  EXPECT_LT(steps.mean_length, 1e-9);
}

// The variation each shape has alone (its noise) shrinks under the steps:
// after them, the shapes lie nearer the population's mean shape (aligned)
// than before.
TEST(EnsembleEntropy, StepsShrinkWhatOneShapeAloneHas) {
  const Population shapes = population(6, 0.05, 5);
  const CorrespondenceSteps steps = EnsembleEntropy().steps(shapes.shapes, shapes.spacings);
  std::vector<PointSet> stepped;
  for (std::size_t k = 0; k < shapes.shapes.size(); ++k) stepped.push_back(shapes.shapes[k] + steps.steps[k]);
  const auto spread = [](const std::vector<PointSet>& set) {
    const ProcrustesAlignment aligned = align_procrustes(set, true);
    PointSet mean = PointSet::Zero(kParticles, 3);
    for (const PointSet& shape : aligned.aligned) mean += shape / double(aligned.aligned.size());
    double off = 0;
    for (const PointSet& shape : aligned.aligned) off += (shape - mean).squaredNorm() / mean.squaredNorm();
    return off;
  };
  const double before = spread(shapes.shapes), after = spread(stepped);
  EXPECT_LT(after, 0.95 * before) << "before " << before << ", after " << after;
}

}  // namespace
}  // namespace meshparticles::testing
