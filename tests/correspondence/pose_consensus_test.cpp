// correspondence/pose_consensus: the population chooses among the poses a
// shape's own fit leaves open.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_consensus.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

// A sphere's points with two bumps (up and along x), and the same shape
// turned half round about y: a pose a fit might take for it.
PointSet bumped_sphere(double height) {
  PointSet points = alignment_points(generate_mesh("sphere"));
  const Eigen::RowVector3d up(0, 0, 1), along(1, 0, 0);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::RowVector3d u = points.row(i).normalized();
    points.row(i) *= 1 + height * (std::exp(-(1 - u.dot(up)) / 0.05) + 0.5 * std::exp(-(1 - u.dot(along)) / 0.05));
  }
  return points;
}

PointSet half_turned(const PointSet& points) {
  return points * Eigen::Vector3d(-1, 1, -1).asDiagonal();  // about y
}

TEST(PopulationAlignment, ThePopulationChoosesAmongThePosesAFitLeavesOpen) {
  const PointSet right = bumped_sphere(0.2), other_right = bumped_sphere(0.15);
  // Shape 1's own fit chose the turned pose, shape 2's the right one.
  const PoseCandidates candidates({{right}, {half_turned(other_right), other_right}, {other_right, half_turned(other_right)}, {right}});
  std::vector<std::vector<double>> distances;
  for (std::size_t k = 0; k < candidates.shapes(); ++k) distances.push_back(candidates.distances(k));
  EXPECT_TRUE(distances[0].empty());
  EXPECT_EQ(distances[1].size(), 2u * (1 + 2 + 1));  // each candidate to every reference's candidates
  const std::vector<PoseChoice> choices = candidates.choose(distances);
  EXPECT_EQ(choices[0].chosen, 0u);
  EXPECT_EQ(choices[0].ratio, 0.0);  // one candidate: nothing to choose
  EXPECT_EQ(choices[1].chosen, 1u);
  EXPECT_EQ(choices[2].chosen, 0u);
  EXPECT_LT(choices[1].ratio, 0.9);
  EXPECT_LT(choices[2].ratio, 0.9);
  // Two shapes: the other is the template, whose fit already chose.
  const PoseCandidates pair({{right}, {half_turned(other_right), other_right}});
  EXPECT_EQ(pair.choose({pair.distances(0), pair.distances(1)})[1].chosen, 0u);
}


}  // namespace
}  // namespace meshparticles::testing
