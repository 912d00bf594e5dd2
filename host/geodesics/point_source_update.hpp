#pragma once
// The triangle update fast marching and the fast iterative method share:
// C's distance from X (at the origin of the frame, distance dx) and Y (at
// (frame.length_xy, 0), distance dy) with the source placed in the
// triangle's plane at those distances, on the far side of XY. The device's
// copy is kernels/point_source_update.h (in float): keep the two in step.
#include <algorithm>
#include <cmath>

#include "geodesics/triangle_stencils.hpp"
#include "mesh/vec3.hpp"

namespace meshparticles {

// +inf when the source's straight line to C does not pass through edge XY,
// leaving C to other stencils and edges.
inline double point_source_update(const PlanarFrame& s, double dx, double dy) {
  const double base = s.length_xy;
  const double source_x = (dx * dx - dy * dy + base * base) / (2 * base);
  const double height_squared = dx * dx - source_x * source_x;
  // Computed whether or not the update applies, and chosen at the end: about
  // half the updates miss the edge, too unpredictable for a branch.
  const double source_y = std::sqrt(std::max(height_squared, 0.0));
  // Where the segment source -> C crosses the x-axis (C has c_y < 0).
  const double t = source_y / (source_y - s.c_y);
  const double crossing = source_x + t * (s.c_x - source_x);
  const double ex = s.c_x - source_x, ey = s.c_y - source_y;
  const double distance = std::sqrt(ex * ex + ey * ey);  // not std::hypot: its overflow care costs a third of the solve
  // Negative height: dx, dy, base violate the triangle inequality. The
  // crossing test also catches 0/0 on degenerate triangles.
  const bool applies = (height_squared >= 0) & (crossing >= 0) & (crossing <= base);
  return applies ? distance : INFINITY;
}

// Fast marching's frame for `point` from the corners `x` and `y`: x at the
// origin, y on the positive x-axis, the point below it (the update's C for
// a point inside a triangle: particles/widest_hole).
inline PlanarFrame point_frame(const Vec3& x, const Vec3& y, const Vec3& point) {
  const Vec3 along = y - x, to = point - x;
  const double base = norm(along);
  const double c_x = dot(to, along) / base;
  const double c_y = -norm(to - (c_x / base) * along);
  return {float(base), float(c_x), float(c_y)};
}

}  // namespace meshparticles
