// correspondence/ellipsoid_body: the robust quadric under a shape's features.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles::testing {
namespace {

// The robust quadric finds a radii shape's own axes and radii through its
// bump and knob (the moments' axes a bump tilts by degrees); a torus has no body.
TEST(EllipsoidBody, FindsTheAxesAndRadiiUnderTheFeatures) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const EllipsoidVariant shape = generate_ellipsoid_variant(seed, 900, EllipsoidFamily::radii);
    const std::optional<EllipsoidBody> body = ellipsoid_body(vertex_points(shape.mesh));
    ASSERT_TRUE(body) << seed;
    const std::array<double, 3> radii{shape.axes.x, shape.axes.y, shape.axes.z};
    const auto entry = [&](int row, int column) {
      const Vec3& r = shape.pose.rotation[std::size_t(row)];
      return column == 0 ? r.x : column == 1 ? r.y : r.z;
    };
    for (int k = 0; k < 3; ++k) {
      // The true axis this one lies along (a column of the pose's rotation), and its radius.
      double best = 0;
      int along = 0;
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d axis(entry(0, j), entry(1, j), entry(2, j));
        const double cosine = std::abs(body->axes.row(k).dot(axis));
        if (cosine > best) {
          best = cosine;
          along = j;
        }
      }
      EXPECT_GT(best, std::cos(std::numbers::pi / 180)) << seed << " axis " << k;
      EXPECT_NEAR(body->radii(k) / shape.pose.scale, radii[std::size_t(along)], 0.02) << seed << " axis " << k;
    }
  }
  EXPECT_FALSE(ellipsoid_body(vertex_points(generate_mesh("torus"))));
}


// Taken to its body's unit sphere, a shape's points lie on it where the
// shape has no feature: most within a percent of radius 1.
TEST(EllipsoidBody, TakesTheBodyToTheUnitSphere) {
  const EllipsoidVariant shape = generate_ellipsoid_variant(5, 900, EllipsoidFamily::radii);
  const PointSet points = vertex_points(shape.mesh);
  const std::optional<EllipsoidBody> body = ellipsoid_body(points);
  ASSERT_TRUE(body);
  EXPECT_NEAR(body->axes.determinant(), 1.0, 1e-9);
  EXPECT_GE(body->radii(0), body->radii(1));
  EXPECT_GE(body->radii(1), body->radii(2));
  const Eigen::VectorXd radius = body->to_unit_sphere(points).rowwise().norm();
  std::vector<double> off(std::size_t(radius.size()));
  for (Eigen::Index i = 0; i < radius.size(); ++i) off[std::size_t(i)] = std::abs(radius(i) - 1);
  std::nth_element(off.begin(), off.begin() + std::ptrdiff_t(off.size() / 2), off.end());
  EXPECT_LT(off[off.size() / 2], 0.01);
}

}  // namespace
}  // namespace meshparticles::testing
