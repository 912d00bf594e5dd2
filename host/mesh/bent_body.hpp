#pragma once
// A family of test shapes with a known map and a near symmetry that nothing
// breaks on purpose: elongated bodies bent along an arc, with a waist and
// three small bumps (`generate --population K --family bent`).
//
// The unit sphere's point u goes to the straight body
//   s(u) = r(u) diag(axes) u,  r(u) = 1 - waist_depth exp(-(u_z / kBentBodyWaistWidth)^2)
//                                      + sum_k bump_heights[k] exp(-(1 - u.b_k) / w_k),
// about three times as long along z as across, then bent in the xz plane
// onto an arc of radius R = 2 axes.z / bend_angle, curving towards +x:
//   x = bend(s) = (R - (R - s.x) cos(s.z / R), s.y, (R - s.x) sin(s.z / R)),
// and posed at random as the ellipsoid families: world = scale rotation x +
// translation. A surface point's parameter: unbend its unposed point,
// s = (R - |q|, q.y, R atan2(q.z, -q.x)) with q = x - (R, 0, 0), then
// u = normalize(diag(axes)^-1 s).
//
// Without its bumps a shape is its own turn half round about x (u to
// (u_x, -u_y, -u_z)); only the bumps, small and of each shape's own height,
// tell the true pose from that one.
//
// Bent either way (`--family bent-either`), half the shapes bend towards -x:
// the straight body turned half round its long axis (T = diag(-1, -1, 1)),
// bent as above and turned back, x = T bend(T s), so the bumps keep their
// side. The population's mean is then nearly straight, and its bend a mode
// that goes both ways around it, as real populations' modes do.
#include <array>
#include <cstdint>

#include "mesh/mesh_generator.hpp"

namespace meshparticles {

struct BentBodyBump {
  Vec3 direction;  // on the parameter sphere
  double width;
};
extern const std::array<BentBodyBump, 3> kBentBodyBumps;
constexpr double kBentBodyWaistWidth = 0.35;  // in u_z

struct BentBody {
  SurfaceMesh mesh;  // posed
  Vec3 axes{};       // the straight body's, z the long one
  double waist_depth = 0;
  std::array<double, 3> bump_heights{};
  double bend_angle = 0;  // radians, the whole axis's turn
  double bend_radius = 0;
  int bend_side = 1;  // +1: towards +x; -1: towards -x, x = T bend(T s)
  ShapePose pose;
};

// Each across radius within 10% of 0.5 (their order swaps), the long one
// within 10% of 1.5, the waist 0.1 to 0.35 deep, each bump 0.05 to 0.2 high,
// the bend 30 to 90 degrees; about `vertices` vertices. Bent either way,
// each shape draws its side too (the one-way family's shapes unchanged).
enum class BendSides { one, either };
BentBody generate_bent_body(std::uint64_t seed, std::size_t vertices, BendSides sides = BendSides::one);

}  // namespace meshparticles
