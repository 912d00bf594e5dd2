#pragma once
// A march's distance to a point inside a triangle, from the distances it
// gave the triangle's corners.
#include <array>
#include <cmath>
#include <limits>

#include "geodesics/point_source_update.hpp"
#include "mesh/vec3.hpp"

namespace meshparticles {

// Through each edge whose two corners have a distance, fast marching's own
// triangle update with `at` in place of the third corner (the source laid
// in the triangle's plane on the far side of the edge); through a corner
// where that is all there is, or nearer. A corner with no distance is
// +inf. Through a corner alone a point in the middle of a triangle reads up
// to a third of an edge too far, where a move's gain is a few thousandths
// of a spacing.
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
    const Vec3 axis = corner[y] - corner[x];
    const double base = norm(axis);
    if (base == 0) continue;
    const Vec3 unit = (1 / base) * axis;
    const Vec3 from_x = at - corner[x];
    const double along = dot(from_x, unit);
    const double off = norm(from_x - along * unit);
    nearest = std::min(nearest, point_source_update(PlanarFrame{float(base), float(along), float(-off)}, dx, dy));
  }
  return nearest;
}

}  // namespace meshparticles
