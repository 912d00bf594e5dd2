#pragma once
// A march's distances at a triangle's three corners, read as one source
// laid in the triangle's plane: the distance anywhere inside the triangle
// is then a straight line, so the farthest point from several sources is
// plane geometry (particles/cavity_centre). Fast marching lays a source
// out the same way from two corners (geodesics/point_source_update).
#include <array>
#include <cmath>

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
// the straight line plus `offset`.
struct PlanarSource {
  double x = 0, y = 0, offset = 0;
  double distance_to(double px, double py) const { return planar_distance(px - x, py - y) + offset; }
};

// The source whose straight lines give the three corners the differences
// of `corner_distance` (exact for a point source on a plane), raised by
// what the corners' own distances leave over on average (a march's
// distances are a little longer than straight lines, and bend round
// obstacles). The frame must not be degenerate.
inline PlanarSource planar_source(const TriangleFrame& f, const std::array<double, 3>& corner_distance) {
  const double a2 = corner_distance[0] * corner_distance[0], b2 = corner_distance[1] * corner_distance[1],
               c2 = corner_distance[2] * corner_distance[2];
  PlanarSource s;
  s.x = (f.b * f.b + a2 - b2) / (2 * f.b);
  s.y = (f.cx * f.cx + f.cy * f.cy + a2 - c2 - 2 * f.cx * s.x) / (2 * f.cy);
  const double corners[3][2] = {{0, 0}, {f.b, 0}, {f.cx, f.cy}};
  double left_over = 0;
  for (int k = 0; k < 3; ++k) left_over += corner_distance[k] - planar_distance(corners[k][0] - s.x, corners[k][1] - s.y);
  s.offset = left_over / 3;
  return s;
}

}  // namespace meshparticles
