#pragma once
// A march's distances at a triangle's three corners, read as one source
// laid in the triangle's plane: the distance anywhere inside the triangle
// is then a straight line, so the farthest point from several sources is
// plane geometry (particles/cavity_centre). Fast marching lays a source
// out the same way from two corners (geodesics/point_source_update).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mesh/surface_mesh.hpp"
#include "mesh/vec3.hpp"

namespace meshparticles {

// A triangle's own frame: its first corner at the origin, its second on the
// x-axis at (b, 0), its third above it at (cx, cy).
struct TriangleFrame {
  Vec3 origin, ex, ey;
  double b = 0, cx = 0, cy = 0;

  bool degenerate() const { return !(b > 0) || !(cy > 0); }
  Vec3 point(double x, double y) const { return origin + x * ex + y * ey; }
  std::array<double, 2> plane(const Vec3& p) const { return {dot(p - origin, ex), dot(p - origin, ey)}; }
  // The corners' weights of (x, y).
  std::array<double, 3> weights(double x, double y) const {
    const double w2 = y / cy, w1 = (x - w2 * cx) / b;
    return {1 - w1 - w2, w1, w2};
  }
  bool holds(double x, double y) const {
    constexpr double kSlack = 1e-9;  // a point on an edge, computed, may stray a rounding off it
    const std::array<double, 3> w = weights(x, y);
    return w[0] >= -kSlack && w[1] >= -kSlack && w[2] >= -kSlack;
  }
};

inline TriangleFrame triangle_frame(const SurfaceMesh& mesh, std::uint32_t triangle) {
  const Triangle& t = mesh.triangles()[triangle];
  const auto& p = mesh.positions();
  TriangleFrame f;
  f.origin = p[t[0]];
  const Vec3 ab = p[t[1]] - f.origin, ac = p[t[2]] - f.origin;
  f.b = norm(ab);
  if (!(f.b > 0)) return f;
  f.ex = (1 / f.b) * ab;
  f.cx = dot(ac, f.ex);
  const Vec3 up = ac - f.cx * f.ex;
  f.cy = norm(up);
  if (f.cy > 0) f.ey = (1 / f.cy) * up;
  return f;
}

inline double planar_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

// A source at (x, y) in a triangle's frame; a point's distance from it is
// the straight line plus `offset`. Where no source fits the corners'
// distances (a sliver, across whose height they differ faster than any
// distance can), the reading is also held within what the corners allow
// by the triangle inequality: no nearer than a corner's distance less the
// way to it, no farther than plus, which makes it a corner's own there.
struct PlanarSource {
  double x = 0, y = 0, offset = 0;
  bool bounded = false;                  // held within the corners' bounds
  std::array<double, 3> corner_distance{};
  std::array<std::array<double, 2>, 3> corner{};  // in the frame
  double distance_to(double px, double py) const {
    const double straight = planar_distance(px - x, py - y) + offset;
    if (!bounded) return straight;
    double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double way = planar_distance(px - corner[k][0], py - corner[k][1]);
      low = std::max(low, corner_distance[k] - way);
      high = std::min(high, corner_distance[k] + way);
    }
    return std::min(std::max(straight, low), high);
  }
};

// The source whose straight lines give the three corners the differences
// of `corner_distance` (exact for a point source on a plane), raised by
// what the corners' own distances leave over on average (a march's
// distances are a little longer than straight lines, and bend round
// obstacles). Where the corners leave over different amounts, its readings
// are bounded (PlanarSource::bounded): on a sliver of turbine at 1,024, a
// corner a twelfth too far in one ball moved the source so that the
// corner beside it read a tenth of a spacing nearer than its own distance.
// The frame must not be degenerate.
inline PlanarSource planar_source(const TriangleFrame& f, const std::array<double, 3>& corner_distance) {
  const double a2 = corner_distance[0] * corner_distance[0], b2 = corner_distance[1] * corner_distance[1],
               c2 = corner_distance[2] * corner_distance[2];
  PlanarSource s;
  s.x = (f.b * f.b + a2 - b2) / (2 * f.b);
  s.y = (f.cx * f.cx + f.cy * f.cy + a2 - c2 - 2 * f.cx * s.x) / (2 * f.cy);
  s.corner = {{{0, 0}, {f.b, 0}, {f.cx, f.cy}}};
  std::array<double, 3> left_over{};
  for (int k = 0; k < 3; ++k) {
    left_over[k] = corner_distance[k] - planar_distance(s.corner[k][0] - s.x, s.corner[k][1] - s.y);
  }
  s.offset = (left_over[0] + left_over[1] + left_over[2]) / 3;
  // Rounding's share of the corners' distances: below it they agree.
  constexpr double kAgree = 1e-6;
  const double scale = std::max({corner_distance[0], corner_distance[1], corner_distance[2], f.b});
  for (int k = 0; k < 3; ++k) s.bounded = s.bounded || std::abs(left_over[k] - s.offset) > kAgree * scale;
  s.corner_distance = corner_distance;
  return s;
}

}  // namespace meshparticles
