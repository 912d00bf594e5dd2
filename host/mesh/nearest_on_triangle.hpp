#pragma once
// The point of a triangle nearest to a point in space, as barycentric
// weights (Ericson, Real-Time Collision Detection, 5.1.5: by the Voronoi
// regions of the corners, then the edges, then the face). One definition
// for the particles that move on the surface and for the alignment's
// closest points.
#include <array>

#include "mesh/vec3.hpp"

namespace meshparticles {

inline std::array<double, 3> nearest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0)) return {1, 0, 0};  // a degenerate triangle: its first corner
  const double v = vb / denominator, w = vc / denominator;
  return {1 - v - w, v, w};
}

inline Vec3 at_weights(const std::array<double, 3>& weights, Vec3 a, Vec3 b, Vec3 c) {
  return weights[0] * a + weights[1] * b + weights[2] * c;
}

}  // namespace meshparticles
