#pragma once
// A march's distance to a point inside a triangle, from the distances it
// gave the triangle's corners.
#include <array>
#include <cmath>
#include <limits>

#include "geodesics/point_source_update.hpp"
#include "mesh/vec3.hpp"

namespace meshparticles {

// Fast marching's frame for `point` from the corners `x` and `y`: x at the
// origin, y on the positive x-axis, the point below it.
inline PlanarFrame point_frame(const Vec3& x, const Vec3& y, const Vec3& point) {
  const Vec3 along = y - x, to = point - x;
  const double base = norm(along);
  const double c_x = dot(to, along) / base;
  const double c_y = -norm(to - (c_x / base) * along);
  return {float(base), float(c_x), float(c_y)};
}

// Through each edge whose two corners have a distance, fast marching's own
// triangle update with `at` in place of the third corner (the source laid
// in the triangle's plane on the far side of the edge; +inf on an edge of
// no length); through a corner where that is all there is, or nearer. A
// corner with no distance is +inf. Through a corner alone a point in the
// middle of a triangle reads up to a third of an edge too far, where a
// move's gain is a few thousandths of a spacing.
inline double distance_in_triangle(const std::array<Vec3, 3>& corner, const std::array<double, 3>& corner_distance,
                                   const Vec3& at) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int x = 0; x < 3; ++x) {
    const double dx = corner_distance[x];
    if (std::isinf(dx)) continue;
    nearest = std::min(nearest, dx + distance(corner[x], at));
    const int y = (x + 1) % 3;
    const double dy = corner_distance[y];
    if (std::isinf(dy)) continue;
    nearest = std::min(nearest, point_source_update(point_frame(corner[x], corner[y], at), dx, dy));
  }
  return nearest;
}

}  // namespace meshparticles
