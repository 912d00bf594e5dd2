// A march's distances at a triangle's three corners, read as one source
// laid in the triangle's plane: the distance anywhere inside the triangle
// is then a straight line, so the farthest point from several sources is
// plane geometry (cavity_centre.h). Fast marching lays a source out the
// same way from two corners (point_source_update.h).
//
// In double, one definition for the host (C++) and the kernels (OpenCL C
// with cl_khr_fp64): every operation as written, no fused multiply-add
// (the kernels build with FP_CONTRACT off, the host with -ffp-contract=off
// on any CPU: CMakeLists.txt), and max and min spelt out as std::max and
// std::min compare, so that both compute the same bits.
#ifndef PLANAR_SOURCE_H
#define PLANAR_SOURCE_H

#include "host_or_device.h"

typedef struct {
  double x, y, z;
} vec3d;

static inline vec3d vec3d_minus(vec3d a, vec3d b) {
  vec3d d = {a.x - b.x, a.y - b.y, a.z - b.z};
  return d;
}
static inline double vec3d_dot(vec3d a, vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double vec3d_distance(vec3d a, vec3d b) {
  const vec3d d = vec3d_minus(a, b);
  return sqrt(vec3d_dot(d, d));
}
// std::max and std::min: the first argument unless the second is larger
// (smaller).
static inline double larger(double a, double b) { return a < b ? b : a; }
static inline double smaller(double a, double b) { return b < a ? b : a; }

static inline double planar_distance(double dx, double dy) { return sqrt(dx * dx + dy * dy); }

// A triangle's own frame: its first corner at the origin, its second on the
// x-axis at (b, 0), its third above it at (cx, cy).
typedef struct {
  vec3d origin, ex, ey;
  double b, cx, cy;
} plane_frame;

static inline plane_frame frame_of_corners(vec3d a, vec3d b, vec3d c) {
  plane_frame f;
  const vec3d zero = {0, 0, 0};
  f.origin = a;
  f.ex = zero;
  f.ey = zero;
  f.b = f.cx = f.cy = 0;
  const vec3d ab = vec3d_minus(b, a), ac = vec3d_minus(c, a);
  f.b = sqrt(vec3d_dot(ab, ab));
  if (!(f.b > 0)) return f;
  const double to_unit = 1 / f.b;
  f.ex.x = to_unit * ab.x;
  f.ex.y = to_unit * ab.y;
  f.ex.z = to_unit * ab.z;
  f.cx = vec3d_dot(ac, f.ex);
  vec3d up;
  up.x = ac.x - f.cx * f.ex.x;
  up.y = ac.y - f.cx * f.ex.y;
  up.z = ac.z - f.cx * f.ex.z;
  f.cy = sqrt(vec3d_dot(up, up));
  if (f.cy > 0) {
    const double to_unit_up = 1 / f.cy;
    f.ey.x = to_unit_up * up.x;
    f.ey.y = to_unit_up * up.y;
    f.ey.z = to_unit_up * up.z;
  }
  return f;
}

static inline int frame_degenerate(plane_frame f) { return !(f.b > 0) || !(f.cy > 0); }
// A point of space laid in the frame's plane: its x and y.
static inline double frame_x(plane_frame f, vec3d p) { return vec3d_dot(vec3d_minus(p, f.origin), f.ex); }
static inline double frame_y(plane_frame f, vec3d p) { return vec3d_dot(vec3d_minus(p, f.origin), f.ey); }
// The point of space at (x, y).
static inline vec3d frame_point(plane_frame f, double x, double y) {
  vec3d p;
  p.x = f.origin.x + x * f.ex.x + y * f.ey.x;
  p.y = f.origin.y + x * f.ex.y + y * f.ey.y;
  p.z = f.origin.z + x * f.ex.z + y * f.ey.z;
  return p;
}
// The corners' weights of (x, y): w[0], w[1], w[2].
static inline void frame_weights(plane_frame f, double x, double y, double* w) {
  w[2] = y / f.cy;
  w[1] = (x - w[2] * f.cx) / f.b;
  w[0] = 1 - w[1] - w[2];
}
static inline int frame_holds(plane_frame f, double x, double y) {
  const double slack = 1e-9;  // a point on an edge, computed, may stray a rounding off it
  double w[3];
  frame_weights(f, x, y, w);
  return w[0] >= -slack && w[1] >= -slack && w[2] >= -slack;
}
// Corner k (0, 1, 2) of the frame: its x and y.
static inline double frame_corner_x(plane_frame f, int k) { return k == 0 ? 0 : (k == 1 ? f.b : f.cx); }
static inline double frame_corner_y(plane_frame f, int k) { return k == 2 ? f.cy : 0; }

// A source at (x, y) in a triangle's frame; a point's distance from it is
// the straight line plus `offset`. Where no source fits the corners'
// distances (a sliver, across whose height they differ faster than any
// distance can), the reading is also held within what the corners allow
// by the triangle inequality: no nearer than a corner's distance less the
// way to it, no farther than plus, which makes it a corner's own there.
typedef struct {
  double x, y, offset;
  int bounded;  // held within the corners' bounds
  double corner_distance[3];
} planar_source;

// The source whose straight lines give the three corners the differences
// of their distances d0, d1, d2 (exact for a point source on a plane),
// raised by what the corners' own distances leave over on average (a
// march's distances are a little longer than straight lines, and bend
// round obstacles). Where the corners leave over different amounts, its
// readings are bounded (planar_source.bounded): on a sliver of turbine at
// 1,024, a corner a twelfth too far in one ball moved the source so that
// the corner beside it read a tenth of a spacing nearer than its own
// distance. The frame must not be degenerate.
static inline planar_source planar_source_of(plane_frame f, double d0, double d1, double d2) {
  const double a2 = d0 * d0, b2 = d1 * d1, c2 = d2 * d2;
  planar_source s;
  s.x = (f.b * f.b + a2 - b2) / (2 * f.b);
  s.y = (f.cx * f.cx + f.cy * f.cy + a2 - c2 - 2 * f.cx * s.x) / (2 * f.cy);
  s.corner_distance[0] = d0;
  s.corner_distance[1] = d1;
  s.corner_distance[2] = d2;
  double left_over[3];
  for (int k = 0; k < 3; ++k) {
    left_over[k] = s.corner_distance[k] - planar_distance(frame_corner_x(f, k) - s.x, frame_corner_y(f, k) - s.y);
  }
  s.offset = (left_over[0] + left_over[1] + left_over[2]) / 3;
  // Rounding's share of the corners' distances: below it they agree.
  const double agree = 1e-6;
  const double scale = larger(larger(larger(d0, d1), d2), f.b);
  s.bounded = 0;
  for (int k = 0; k < 3; ++k) s.bounded = s.bounded || fabs(left_over[k] - s.offset) > agree * scale;
  return s;
}

// The distance of (px, py) from source `s` of frame `f`.
static inline double planar_source_distance(plane_frame f, planar_source s, double px, double py) {
  const double straight = planar_distance(px - s.x, py - s.y) + s.offset;
  if (!s.bounded) return straight;
  double low = -(double)INFINITY, high = (double)INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double way = planar_distance(px - frame_corner_x(f, k), py - frame_corner_y(f, k));
    low = larger(low, s.corner_distance[k] - way);
    high = smaller(high, s.corner_distance[k] + way);
  }
  return smaller(larger(straight, low), high);
}

#endif
