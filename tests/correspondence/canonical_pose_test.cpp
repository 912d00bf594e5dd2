// correspondence/canonical_pose: a shape's intrinsic canonical form (landmark
// MDS of its geodesic distances), which bending hardly changes, and the pose
// it chooses on a body bent the other way from the template.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "correspondence/canonical_pose.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

// A thin slab (3 long, 1 wide, 0.16 thick) with two bumps of unlike height
// on its top face, bent along its length onto an arc turning by `degrees`
// (towards +z, or -z for negative degrees): so thin that the bend stretches
// its faces by under 5%, nearly isometric. Vertex v is the same surface
// point at every bend.
SurfaceMesh bent_slab(double degrees) {
  const SurfaceMesh sphere = generate_mesh_at("sphere", 1500);
  std::vector<Vec3> positions = sphere.positions();
  const double angle = degrees * std::numbers::pi / 180;
  for (Vec3& p : positions) {
    const Eigen::Vector3d u = Eigen::Vector3d(p.x, p.y, p.z).normalized();
    double x = 1.5 * u.x(), y = 0.5 * u.y(), z = 0.08 * u.z();
    if (z > 0) {
      z += 0.12 * std::exp(-((x - 0.7) * (x - 0.7) + (y - 0.15) * (y - 0.15)) / 0.04) +
           0.07 * std::exp(-((x + 0.5) * (x + 0.5) + (y + 0.2) * (y + 0.2)) / 0.04);
    }
    if (angle != 0) {
      const double radius = 3 / angle;  // signed: the arc's centre at z = radius
      const double across = radius - z;
      p = {across * std::sin(x / radius), y, radius - across * std::cos(x / radius)};
    } else {
      p = {x, y, z};
    }
  }
  return SurfaceMesh(positions, sphere.triangles());
}

// The root mean square distance between rows of `a` and `b` (row v with
// row v), after the proper rigid motion that lays `a` best over `b`.
double fitted_rms(const PointSet& a, const PointSet& b) {
  const PointSet ca = a.rowwise() - a.colwise().mean(), cb = b.rowwise() - b.colwise().mean();
  const Eigen::Matrix3d rotation = best_rotation(ca, cb);
  return std::sqrt((ca * rotation.transpose() - cb).rowwise().squaredNorm().mean());
}

PointSet at_unit_area(const SurfaceMesh& mesh) { return vertex_points(mesh) / std::sqrt(mesh.area()); }

TEST(CanonicalForm, ABendHardlyChangesIt) {
  const SurfaceMesh straight = bent_slab(0), bent = bent_slab(240);
  const std::optional<PointSet> straight_form = canonical_form(straight), bent_form = canonical_form(bent);
  ASSERT_TRUE(straight_form && bent_form);
  // Rows: the same surface points. As they lie, a bend of 240 degrees sets
  // them far apart; in canonical form it hardly does (nor could the
  // quadratic trend that `straighten` takes out undo a bend so deep).
  const double apart = fitted_rms(at_unit_area(straight), at_unit_area(bent));
  const double canonical_apart = fitted_rms(*straight_form, *bent_form);
  EXPECT_GT(apart, 0.05);
  EXPECT_LT(canonical_apart, 0.25 * apart) << apart;
}

TEST(CanonicalForm, IsTheMeshsOwnNotItsMirrorImage) {
  const SurfaceMesh mesh = bent_slab(60);
  std::vector<Vec3> mirrored = mesh.positions();
  for (Vec3& p : mirrored) p.x = -p.x;
  // The same geodesic distances, the triangles now wound inwards: the mirror image.
  const SurfaceMesh mirror(mirrored, mesh.triangles());
  const std::optional<PointSet> form = canonical_form(mesh), mirror_form = canonical_form(mirror);
  ASSERT_TRUE(form && mirror_form);
  PointSet reflected = *mirror_form;
  reflected.col(0) = -reflected.col(0);
  EXPECT_LT(fitted_rms(reflected, *form), 0.01);
  EXPECT_GT(fitted_rms(*mirror_form, *form), 0.05);
}

TEST(CanonicalPose, LaysABodyBentTheOtherWayOverTheTemplateByItsBumps) {
  const SurfaceMesh template_mesh = bent_slab(60);
  // The same body bent the other way, turned, moved and enlarged.
  const SurfaceMesh other_way = bent_slab(-60);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  std::vector<Vec3> posed = other_way.positions();
  for (Vec3& p : posed) {
    const Eigen::Vector3d q = 1.7 * turn * Eigen::Vector3d(p.x, p.y, p.z) + Eigen::Vector3d(4, -2, 1);
    p = {q.x(), q.y(), q.z()};
  }
  const SurfaceMesh shape(posed, other_way.triangles());
  const PointSet template_points = canonical_frame(template_mesh).apply(vertex_points(template_mesh));
  const CanonicalTemplate reference(template_mesh, template_points, PoseChoiceOptions{});
  const std::optional<CanonicalPose> pose = choose_pose_canonically(reference, shape);
  ASSERT_TRUE(pose);
  // Vertex v is the same point on both: each template vertex's partner lies near it, along the surface.
  const PointSet own = at_unit_area(shape);
  double off = 0;
  for (std::size_t v = 0; v < pose->pairs.size(); ++v) off += (own.row(pose->pairs[v]) - own.row(Eigen::Index(v))).norm();
  EXPECT_LT(off / double(pose->pairs.size()), 0.05);
  // The pose lays each shape vertex near the template's, bumps on bumps;
  // the rigid fit, which matches the bend, turns the shape half round.
  const auto mean_apart = [&](const MeshAlignment& alignment) {
    return (alignment.to_common.apply(vertex_points(shape)) - template_points).rowwise().norm().mean();
  };
  const double canonical = mean_apart(pose->alignment);
  const double rigid = mean_apart(align_to_template(shape, template_points, canonical_frame(template_mesh), PoseChoiceOptions{}));
  EXPECT_LT(canonical, 0.15);
  EXPECT_GT(rigid, 2 * canonical);
  EXPECT_TRUE(pose->alignment.relief.measured);
  EXPECT_GT(pose->alignment.relief.agreement, 0.5);
}

}  // namespace
}  // namespace meshparticles::testing
