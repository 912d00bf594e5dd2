#pragma once
// A march's distances at a triangle's three corners, read as one source
// laid in the triangle's plane (kernels/planar_source.h, written once for
// the host and the device): here, a mesh's triangle's frame and the
// conversions between the host's points and the shared code's.
#include <cstdint>

#include "mesh/surface_mesh.hpp"
#include "mesh/vec3.hpp"
#include "planar_source.h"

namespace meshparticles {

inline vec3d to_vec3d(const Vec3& p) { return {p.x, p.y, p.z}; }
inline Vec3 to_vec3(const vec3d& p) { return {p.x, p.y, p.z}; }

// Triangle `triangle`'s own frame (plane_frame: its first corner at the
// origin, its second on the x-axis).
inline plane_frame triangle_frame(const SurfaceMesh& mesh, std::uint32_t triangle) {
  const Triangle& t = mesh.triangles()[triangle];
  const auto& p = mesh.positions();
  return frame_of_corners(to_vec3d(p[t[0]]), to_vec3d(p[t[1]]), to_vec3d(p[t[2]]));
}

}  // namespace meshparticles
