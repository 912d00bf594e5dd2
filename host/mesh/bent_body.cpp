#include "mesh/bent_body.hpp"

#include <cmath>
#include <numbers>

#include "common/random.hpp"

namespace meshparticles {

// Off every plane of the shape's symmetry, and none the image of another
// under its half turn about x: the bumps alone fix the pose.
const std::array<BentBodyBump, 3> kBentBodyBumps = {{
    {normalized({-1.0, 0.3, 0.5}), 0.03},   // the convex side, towards +z
    {normalized({0.2, 1.0, -0.4}), 0.03},   // the +y side, towards -z
    {normalized({0.6, -0.8, 0.15}), 0.03},  // the concave side's -y flank, in the waist
}};

namespace {

double uniform_in(SplitMix64& random, double low, double high) { return low + (high - low) * random.uniform(); }

struct BentShape {
  Vec3 axes;
  double waist_depth;
  std::array<double, 3> bump_heights;
  double bend_radius;
  int bend_side = 1;

  // T = diag(-1, -1, 1) for a body bent towards -x (its own inverse).
  Vec3 sided(Vec3 x) const { return bend_side > 0 ? x : Vec3{-x.x, -x.y, x.z}; }

  Vec3 straight_point(Vec3 u) const {
    double r = 1 - waist_depth * std::exp(-(u.z / kBentBodyWaistWidth) * (u.z / kBentBodyWaistWidth));
    for (std::size_t k = 0; k < kBentBodyBumps.size(); ++k) {
      r += bump_heights[k] * std::exp(-(1 - dot(u, kBentBodyBumps[k].direction)) / kBentBodyBumps[k].width);
    }
    return r * Vec3{axes.x * u.x, axes.y * u.y, axes.z * u.z};
  }

  Vec3 bend(Vec3 s) const {
    const double across = bend_radius - s.x, angle = s.z / bend_radius;
    return {bend_radius - across * std::cos(angle), s.y, across * std::sin(angle)};
  }

  Vec3 unbend(Vec3 x) const {
    const double qx = x.x - bend_radius;
    return {bend_radius - std::hypot(qx, x.z), x.y, bend_radius * std::atan2(x.z, -qx)};
  }

  Vec3 surface_point(Vec3 u) const { return sided(bend(sided(straight_point(normalized(u))))); }

  Vec3 parameter_of(Vec3 x) const {
    const Vec3 s = sided(unbend(sided(x)));
    return normalized({s.x / axes.x, s.y / axes.y, s.z / axes.z});
  }
};

}  // namespace

BentBody generate_bent_body(std::uint64_t seed, std::size_t vertices, BendSides sides) {
  SplitMix64 random(seed);
  BentShape shape{};
  shape.axes = {0.5 * uniform_in(random, 0.9, 1.1), 0.5 * uniform_in(random, 0.9, 1.1),
                1.5 * uniform_in(random, 0.9, 1.1)};
  shape.waist_depth = uniform_in(random, 0.1, 0.35);
  for (double& height : shape.bump_heights) height = uniform_in(random, 0.05, 0.2);
  const double bend_angle = uniform_in(random, 30, 90) * std::numbers::pi / 180;
  shape.bend_radius = 2 * shape.axes.z / bend_angle;
  if (sides == BendSides::either) shape.bend_side = random.uniform() < 0.5 ? -1 : 1;
  // The mesh's vertices placed by their parameter (the length's stretch
  // shared with the girth's, not piled at the middle as a central
  // projection would), and any point projected through its parameter.
  PosedShape posed = mesh_and_pose_shape(
      random, vertices, [&shape](Vec3 u) { return shape.surface_point(u); },
      [&shape](Vec3 x) { return shape.surface_point(shape.parameter_of(x)); });
  return {std::move(posed.mesh), shape.axes,         shape.waist_depth, shape.bump_heights, bend_angle,
          shape.bend_radius,       shape.bend_side, posed.pose};
}

}  // namespace meshparticles
