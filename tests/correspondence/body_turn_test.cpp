// correspondence/body_turn: the profile grid and its 24 turns, a shape's
// feature profile off its body, the agreement of two profiles under each
// turn, which picks the turn that lays one's features on the other's, and
// the population's turns that choose_body_turns makes of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <cstdint>
#include <optional>
#include <vector>

#include "correspondence/body_turn.hpp"
#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/shape_share.hpp"
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

// The tip of a radii shape's bump, where its pose puts it.
Eigen::Vector3d bump_tip(const EllipsoidVariant& shape) {
  const Vec3 u = kEllipsoidBump.direction;
  const double r = 1 + shape.bump_height;  // the knob's term is nil this far from it
  const Vec3 x{r * shape.axes.x * u.x, r * shape.axes.y * u.y, r * shape.axes.z * u.z};
  const std::array<Vec3, 3>& rows = shape.pose.rotation;
  const Vec3 world = shape.pose.scale * Vec3{dot(rows[0], x), dot(rows[1], x), dot(rows[2], x)} + shape.pose.translation;
  return {world.x, world.y, world.z};
}

// Four radii shapes, each meshed and posed on its own, their radii in
// another order at times, one starting from the wrong one of two poses its
// body allows: each turned by its features' agreement with the others onto
// the template's body and stretched onto its radii, its bump lands where
// the template's stands.
TEST(BodyTurn, EachShapeTakesTheTurnThatLaysItsBumpOnTheTemplates) {
  std::vector<EllipsoidVariant> shapes;
  std::vector<std::optional<SurfaceMesh>> meshes;
  for (std::uint64_t seed = 11; seed <= 14; ++seed) {
    shapes.push_back(generate_ellipsoid_variant(seed, 900, EllipsoidFamily::radii));
    meshes.emplace_back(shapes.back().mesh);
  }
  const Similarity template_frame = canonical_frame(*meshes[0]);
  const PointSet template_points = template_frame.apply(vertex_points(*meshes[0]));
  std::vector<MeshAlignment> alignments(shapes.size());
  alignments[0].to_common = template_frame;
  for (std::size_t k = 1; k < shapes.size(); ++k) {
    alignments[k] = align_to_template(*meshes[k], template_points, template_frame, PoseChoiceOptions{});
  }
  // Shape 2 starts turned half round about the template's longest axis from
  // its fit: a pose its body alone cannot tell from the right one.
  const Eigen::Matrix3d half_turn = Eigen::Vector3d(1, -1, -1).asDiagonal();
  alignments[2].to_common.rotation = half_turn * alignments[2].to_common.rotation;
  alignments[2].to_common.translation = half_turn * alignments[2].to_common.translation;
  ShapeShare share(shapes.size(), 2);
  choose_body_turns(meshes, share, template_points, alignments, PoseChoiceOptions{});
  const auto in_common = [&](std::size_t k, const Eigen::Vector3d& world) -> Eigen::Vector3d {
    const PointSet point = alignments[k].to_common.apply(PointSet(world.transpose()));
    return alignments[k].stretch * point.row(0).transpose() + alignments[k].shift;
  };
  const Eigen::Vector3d centre = template_points.colwise().mean().transpose();
  const Eigen::Vector3d template_tip = in_common(0, bump_tip(shapes[0])) - centre;
  for (std::size_t k = 1; k < shapes.size(); ++k) {
    EXPECT_TRUE(alignments[k].from_principal_axes) << "shape " << k << ": not turned by its body";
    const Eigen::Vector3d tip = in_common(k, bump_tip(shapes[k])) - centre;
    const double degrees = std::acos(std::clamp(tip.normalized().dot(template_tip.normalized()), -1.0, 1.0)) * 180 / std::numbers::pi;
    EXPECT_LT(degrees, 15.0) << "shape " << k;
  }
}

}  // namespace
}  // namespace meshparticles::testing
