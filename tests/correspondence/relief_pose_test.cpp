// correspondence/surface_relief and correspondence/relief_pose: the poses a
// shape's rigid fit leaves open, told apart by where the template's small
// features land after a coarse deformable fit.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "correspondence/relief_pose.hpp"
#include "correspondence/surface_relief.hpp"
#include "fixtures/bent_body.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

// A sphere of about `vertices` vertices (each resolution meshed on its own)
// with a bump up and a smaller one along x, each `height` high.
SurfaceMesh bumped_sphere_mesh(std::size_t vertices, double height) {
  const SurfaceMesh sphere = generate_mesh_at("sphere", vertices);
  std::vector<Vec3> positions = sphere.positions();
  const Eigen::Vector3d up(0, 0, 1), along(1, 0, 0);
  for (Vec3& p : positions) {
    const Eigen::Vector3d u = Eigen::Vector3d(p.x, p.y, p.z).normalized();
    const double r = Eigen::Vector3d(p.x, p.y, p.z).norm() *
                     (1 + height * (std::exp(-(1 - u.dot(up)) / 0.05) + 0.6 * std::exp(-(1 - u.dot(along)) / 0.05)));
    p = {r * u.x(), r * u.y(), r * u.z()};
  }
  return SurfaceMesh(positions, sphere.triangles());
}

MeshAlignment posed(const Eigen::Matrix3d& rotation) {
  MeshAlignment pose;
  pose.to_common.rotation = rotation;
  return pose;
}

const Eigen::Matrix3d kHalfTurn = Eigen::Vector3d(-1, 1, -1).asDiagonal();  // about y
const PoseChoiceOptions kReliefOptions;  // correspond's

TEST(SurfaceRelief, ABumpStandsOffTheSurfaceAndTheRestIsFlat) {
  const SurfaceMesh mesh = bumped_sphere_mesh(2000, 0.2);
  const PointSet points = vertex_points(mesh);
  const Eigen::VectorXd relief = surface_relief(mesh, points);
  Eigen::Index top = 0, bottom = 0, side = 0;
  points.col(2).maxCoeff(&top);
  points.col(2).minCoeff(&bottom);
  points.col(1).minCoeff(&side);
  // A sphere stands off its smoothed self by its curvature alone, the same
  // everywhere; a bump, by more.
  EXPECT_NEAR(relief(bottom), relief(side), 0.1 * relief(side));
  EXPECT_GT(relief(top), relief(bottom) + 0.01);
  // In the points' units: the same mesh twice as large, twice the heights.
  EXPECT_NEAR((surface_relief(mesh, 2 * points) - 2 * relief).norm(), 0, 1e-9 * relief.norm());
}

TEST(SurfaceRelief, AgreementIsTheCorrelationOverPairs) {
  const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(5, 0, 4);
  const std::vector<Eigen::Index> same{0, 1, 2, 3, 4}, reversed{4, 3, 2, 1, 0};
  EXPECT_NEAR(relief_agreement(a, a, same), 1, 1e-12);
  EXPECT_NEAR(relief_agreement(a, 3 * a, same), 1, 1e-12);
  EXPECT_NEAR(relief_agreement(a, a, reversed), -1, 1e-12);
  EXPECT_EQ(relief_agreement(a, Eigen::VectorXd::Ones(5), same), 0);  // flat
}

TEST(ReliefPose, TheRightPoseLaysTheTemplatesFeaturesOverTheShapes) {
  const SurfaceMesh template_mesh = bumped_sphere_mesh(1500, 0.2);
  const PointSet template_points = vertex_points(template_mesh);
  const ReliefTemplate reference(template_mesh, template_points, kReliefOptions);
  const SurfaceMesh shape = bumped_sphere_mesh(2200, 0.15);  // lower bumps, meshed apart
  // Either order: the choice does not lean on the fit's.
  for (const bool right_first : {true, false}) {
    const std::vector<MeshAlignment> poses = right_first ? std::vector{posed(Eigen::Matrix3d::Identity()), posed(kHalfTurn)}
                                                         : std::vector{posed(kHalfTurn), posed(Eigen::Matrix3d::Identity())};
    const ReliefChoice choice = choose_pose_by_relief(reference, shape, poses);
    EXPECT_EQ(choice.chosen, right_first ? 0u : 1u);
    EXPECT_TRUE(choice.relief.measured);
    EXPECT_GT(choice.relief.agreement, 0.8);
    EXPECT_LT(choice.relief.runner_up, choice.relief.agreement - kReliefOptions.close_relief);
    EXPECT_NEAR(choice.relief.runner_up_degrees, 180, 1e-6);
  }
}

// A body of the bent-either family as it was made (its random pose undone):
// bent towards +x (side 1) or -x (side -1) in the xz plane, long along z
// (of seeds 1 to 12, only 10 is bent towards +x).
SurfaceMesh bent_body_as_made(std::uint64_t seed, int side) {
  const BentBody body = generate_bent_body(seed, 1500, BendSides::either);
  EXPECT_EQ(body.bend_side, side) << "seed " << seed;
  std::vector<Vec3> positions = body.mesh.positions();
  for (Vec3& p : positions) p = body.pose.unposed(p);
  return SurfaceMesh(positions, body.mesh.triangles());
}

// `rotation` about the shape's centroid, onto the template's.
MeshAlignment posed_onto(const Eigen::Matrix3d& rotation, const SurfaceMesh& shape, const PointSet& template_points) {
  MeshAlignment pose = posed(rotation);
  pose.to_common.translation =
      template_points.colwise().mean().transpose() - rotation * vertex_points(shape).colwise().mean().transpose();
  return pose;
}

TEST(ReliefPose, TheBumpsDecideOnABodyBentTheTemplatesWay) {
  const SurfaceMesh template_mesh = bent_body_as_made(2, -1);
  const PointSet template_points = vertex_points(template_mesh);
  const SurfaceMesh shape = bent_body_as_made(4, -1);
  const Eigen::Matrix3d about_x = Eigen::Vector3d(1, -1, -1).asDiagonal();  // the unbumped body's own symmetry
  const ReliefChoice choice = choose_pose_by_relief(
      ReliefTemplate(template_mesh, template_points, kReliefOptions), shape,
      {posed_onto(about_x, shape, template_points), posed_onto(Eigen::Matrix3d::Identity(), shape, template_points)});
  EXPECT_EQ(choice.chosen, 1u);
  EXPECT_GT(choice.relief.agreement, 0.5);
  EXPECT_LT(choice.relief.runner_up, choice.relief.agreement - kReliefOptions.close_relief);
}

TEST(ReliefPose, ABendReversedIsNeverTakenForTheHalfTurnThatMatchesItWithConfidence) {
  const SurfaceMesh template_mesh = bent_body_as_made(10, 1);
  const PointSet template_points = vertex_points(template_mesh);
  const ReliefTemplate reference(template_mesh, template_points, kReliefOptions);
  // The half turn about the long axis bends a body bent the other way as
  // the template bends: it matches the silhouette, not the bumps. The raw
  // relief, which the bend itself shapes, took it on each of these 6
  // bodies, agreeing 0.45 to 0.63; less its bend's trend, the true pose is
  // taken, or the agreement stays under weak_relief (canonical_pose then
  // decides).
  const Eigen::Matrix3d about_long_axis = Eigen::Vector3d(-1, -1, 1).asDiagonal();
  std::size_t true_poses = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const SurfaceMesh shape = bent_body_as_made(seed, -1);
    const ReliefChoice choice = choose_pose_by_relief(
        reference, shape,
        {posed_onto(about_long_axis, shape, template_points), posed_onto(Eigen::Matrix3d::Identity(), shape, template_points)});
    true_poses += choice.chosen == 1;
    EXPECT_TRUE(choice.chosen == 1 || choice.relief.agreement < kReliefOptions.weak_relief)
        << "seed " << seed << ": the half turn, agreeing " << choice.relief.agreement;
  }
  EXPECT_GE(true_poses, 5u);
}

TEST(ReliefPose, AShapeWithoutFeaturesLeavesThePosesClose) {
  const SurfaceMesh template_mesh = generate_mesh_at("sphere", 1500);
  const PointSet template_points = vertex_points(template_mesh);
  const SurfaceMesh shape = generate_mesh_at("sphere", 2200);
  const ReliefChoice choice =
      choose_pose_by_relief(ReliefTemplate(template_mesh, template_points, kReliefOptions), shape,
                            {posed(Eigen::Matrix3d::Identity()), posed(kHalfTurn)});
  // Nothing to lay over anything: warned of either way (population_doubts).
  EXPECT_TRUE(choice.relief.agreement < kReliefOptions.weak_relief ||
              choice.relief.runner_up > choice.relief.agreement - kReliefOptions.close_relief)
      << choice.relief.agreement << " " << choice.relief.runner_up;
}

}  // namespace
}  // namespace meshparticles::testing
