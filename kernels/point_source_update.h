// The triangle update of the fast iterative method: C's distance from X (at
// the origin of the frame, distance dx) and Y (at (base, 0), distance dy),
// the source placed in the triangle's plane at those distances on the far
// side of XY; INFINITY when its straight line to C misses edge XY. The host's
// copy, in double, is host/geodesics/point_source_update.hpp: keep the two
// in step.
#ifndef POINT_SOURCE_UPDATE_H
#define POINT_SOURCE_UPDATE_H

static inline float point_source_update(float base, float c_x, float c_y, float dx, float dy) {
  const float source_x = (dx * dx - dy * dy + base * base) / (2.0f * base);
  const float height_squared = dx * dx - source_x * source_x;
  const float source_y = sqrt(fmax(height_squared, 0.0f));
  // Where the segment source -> C crosses the x-axis (C has c_y < 0).
  const float t = source_y / (source_y - c_y);
  const float crossing = source_x + t * (c_x - source_x);
  const float ex = c_x - source_x, ey = c_y - source_y;
  const float distance = sqrt(ex * ex + ey * ey);
  // Negative height: dx, dy, base violate the triangle inequality. The
  // crossing test also catches 0/0 on degenerate triangles.
  const int applies = (height_squared >= 0.0f) & (crossing >= 0.0f) & (crossing <= base);
  return applies ? distance : INFINITY;
}

#endif
