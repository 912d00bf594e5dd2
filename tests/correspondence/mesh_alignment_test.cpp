// correspondence/mesh_alignment: the cube's rotations, the canonical frame,
// a shape's fit onto the template, and the population's medoid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

// The medoid is the shape nearest the others, whatever their order: of
// three spheres scaled 0.9, 1 and 1.2, the middle one; and a shape's
// distance to the population leaves itself out.
TEST(PopulationAlignment, TheMedoidIsTheShapeNearestTheOthers) {
  const PointSet sphere = alignment_points(generate_mesh("sphere"));
  const std::vector<PointSet> shapes{1.2 * sphere, 0.9 * sphere, 1.0 * sphere};
  const AlignedShapes population(shapes);
  EXPECT_EQ(population.medoid(), 2u);
  EXPECT_EQ(AlignedShapes({shapes[2], shapes[0], shapes[1]}).medoid(), 0u);
  EXPECT_EQ(AlignedShapes({shapes[2]}).distance_to_population(shapes[2], 0), 0.0);
  EXPECT_LT(population.distance_to_population(shapes[2], 2), population.distance_to_population(shapes[0], 0));
}


// A shape's points moved: turned about an uneven axis, scaled, shifted.
const Eigen::Matrix3d kTurn = Eigen::AngleAxisd(2.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
SurfaceMesh moved(const SurfaceMesh& mesh, double scale, const Eigen::Vector3d& shift) {
  std::vector<Vec3> positions;
  for (const Vec3& p : mesh.positions()) {
    const Eigen::Vector3d q = scale * (kTurn * Eigen::Vector3d(p.x, p.y, p.z)) + shift;
    positions.push_back({q(0), q(1), q(2)});
  }
  return SurfaceMesh(positions, mesh.triangles());
}

// The 24 proper turns of the cube, each once, the identity first.
TEST(MeshAlignment, CubeRotationsAreTheCubesTwentyFourTurns) {
  const std::vector<Eigen::Matrix3d>& turns = cube_rotations();
  ASSERT_EQ(turns.size(), 24u);
  EXPECT_TRUE(turns.front().isIdentity(0));
  std::set<std::vector<double>> distinct;
  for (const Eigen::Matrix3d& turn : turns) {
    EXPECT_NEAR(turn.determinant(), 1.0, 1e-15);
    EXPECT_TRUE((turn * turn.transpose()).isIdentity(1e-15));
    EXPECT_EQ(turn.cwiseAbs().sum(), 3.0);  // a signed permutation
    distinct.insert(std::vector<double>(turn.data(), turn.data() + 9));
  }
  EXPECT_EQ(distinct.size(), 24u);
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(turn_angle(Eigen::Matrix3d::Identity(), quarter), 90.0, 1e-9);
  EXPECT_NEAR(turn_angle(quarter, quarter), 0.0, 1e-6);
}

// The canonical frame takes a shape to unit area, its centroid to 0 and its
// axes onto x, y, z: the same points however the shape was posed.
TEST(MeshAlignment, TheCanonicalFrameIsTheSameHoweverTheShapeIsPosed) {
  const SurfaceMesh mesh = generate_ellipsoid_variant(2, 600).mesh;
  const SurfaceMesh posed = moved(mesh, 2.5, Eigen::Vector3d(3, -1, 7));
  const Similarity frame = canonical_frame(mesh), posed_frame = canonical_frame(posed);
  EXPECT_NEAR(frame.scale * frame.scale * mesh.area(), 1.0, 1e-12);
  const PointSet a = frame.apply(vertex_points(mesh)), b = posed_frame.apply(vertex_points(posed));
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(a.colwise().mean().norm(), 0.05);  // the vertices' mean, near the surface's centroid
}

// A copy of the template, posed anew: its fit lands on the template exactly.
TEST(MeshAlignment, ACopyOfTheTemplateFitsItExactly) {
  const SurfaceMesh template_mesh = generate_ellipsoid_variant(3, 600).mesh;
  const Similarity template_frame = canonical_frame(template_mesh);
  const PointSet template_points = template_frame.apply(vertex_points(template_mesh));
  const SurfaceMesh copy = moved(template_mesh, 0.4, Eigen::Vector3d(-2, 5, 1));
  const MeshAlignment alignment = align_to_template(copy, template_points, template_frame, PoseChoiceOptions{});
  EXPECT_LT(alignment.rms, 1e-6);
  EXPECT_LT((alignment.to_common.apply(vertex_points(copy)) - template_points).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(alignment.to_common.scale * 0.4, template_frame.scale, 1e-9);
  EXPECT_GT(alignment.runner_up.rms_ratio, PoseChoiceOptions{}.open_pose_ratio);  // no other pose left open
  EXPECT_FALSE(alignment.relief.measured);
}

// The symmetric distance: zero from a shape to itself, the same both ways.
TEST(MeshAlignment, ShapeDistanceIsSymmetricAndZeroOnItself) {
  const PointSet sphere = alignment_points(generate_mesh("sphere"));
  const PointSet larger = 1.1 * sphere;
  const PointsTree sphere_tree(sphere), larger_tree(larger);
  EXPECT_EQ(shape_distance(sphere, sphere_tree, sphere, sphere_tree), 0.0);
  EXPECT_EQ(shape_distance(sphere, sphere_tree, larger, larger_tree),
            shape_distance(larger, larger_tree, sphere, sphere_tree));
  EXPECT_GT(shape_distance(sphere, sphere_tree, larger, larger_tree), 0.0);
}

}  // namespace
}  // namespace meshparticles::testing
