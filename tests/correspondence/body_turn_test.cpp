// correspondence/body_turn: the profile grid and its 24 turns, a shape's
// feature profile off its body, and the agreement of two profiles under
// each turn, which picks the turn that lays one's features on the other's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "correspondence/body_turn.hpp"
#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

TEST(BodyTurn, TheGridSpreadsUnitDirectionsAndTurnsEachOntoItsNearest) {
  const ProfileGrid grid = profile_grid(400);
  ASSERT_EQ(grid.directions.rows(), 400);
  EXPECT_LT((grid.directions.rowwise().norm().array() - 1).abs().maxCoeff(), 1e-12);
  EXPECT_LT(grid.directions.colwise().mean().norm(), 0.01);  // even over the sphere
  ASSERT_EQ(grid.turned.size(), cube_rotations().size());
  for (Eigen::Index g = 0; g < 400; ++g) EXPECT_EQ(grid.turned[0][std::size_t(g)], g);  // the identity
  for (std::size_t t = 0; t < grid.turned.size(); ++t) {
    const Eigen::Matrix3d& turn = cube_rotations()[t];
    for (Eigen::Index g = 0; g < 400; g += 37) {
      const Eigen::RowVector3d turned = grid.directions.row(g) * turn.transpose();
      EXPECT_GT(turned.dot(grid.directions.row(grid.turned[t][std::size_t(g)])), 0.98) << "turn " << t;
    }
  }
}

// A radii shape's profile off its own body: flat where it has no feature,
// standing out at its bump; turned by any of the cube's turns, the
// agreements find that turn.
TEST(BodyTurn, TheAgreementsFindTheTurnBetweenTwoProfiles) {
  const ProfileGrid grid = profile_grid(1000);
  const EllipsoidVariant shape = generate_ellipsoid_variant(2, 900, EllipsoidFamily::radii);
  const PointSet points = vertex_points(shape.mesh);
  const std::optional<EllipsoidBody> body = ellipsoid_body(points);
  ASSERT_TRUE(body);
  const Eigen::VectorXd profile = feature_profile(*body, points, grid.directions);
  ASSERT_EQ(profile.size(), 1000);
  std::vector<double> off(profile.data(), profile.data() + profile.size());
  std::nth_element(off.begin(), off.begin() + 500, off.end());
  EXPECT_LT(std::abs(off[500]), 0.01) << "the body's median";
  EXPECT_GT(profile.maxCoeff(), 0.05) << "the bump";

  const std::vector<double> self = turn_agreements(profile, profile, grid);
  ASSERT_EQ(self.size(), 24u);
  EXPECT_NEAR(self[0], profile.squaredNorm() / 1000, 1e-12 * self[0]);
  for (std::size_t t = 0; t < 24; ++t) {
    const std::vector<double> agreements = turn_agreements(profile, turned_profile(profile, grid, t), grid);
    const std::size_t best = std::size_t(std::max_element(agreements.begin(), agreements.end()) - agreements.begin());
    EXPECT_EQ(best, t);
  }
}

}  // namespace
}  // namespace meshparticles::testing
