// The centres of the cavities of one independent set of spread's evening
// (host/particles/local_farthest_points), one work-item a particle: the
// device twin of the host's proposals, from the same code
// (cavity_centre.h), so the same bits: the host builds this program
// without unsafe math, and nothing here is contracted into fused
// multiply-adds. Needs double precision: without cl_khr_fp64 the file
// holds no kernel, and the host keeps the moves (particles/device_cavity_centres).
#pragma OPENCL FP_CONTRACT OFF

#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

#include "cavity_centre.h"

// One particle's cavity and its share of the scratch (host:
// CavityTask in particles/device_cavity_centres.cpp, the same layout):
// its region, near and further particles are lists[...start] to
// lists[...start + ...size - 1]; its scratch starts at the given offsets
// of each scratch buffer.
typedef struct {
  uint particle, region_start, region_size, near_start, near_size, further_start, further_size;
  uint triangles_at, corners_at, sources_at, table_at, triangle_slots_at, vertex_slots_at;
} cavity_task;

__kernel void cavity_centres(const uint count, __global const cavity_task* tasks, __global const uint* lists,
                             __global const vec3d* positions, __global const uint* corners,
                             __global const uint* fan_start, __global const uint* fans,
                             __global const uint* point_triangles, __global const vec3d* points,
                             __global const ball_entry* entries, __global const uint* ball_start,
                             __global const uint* ball_size, __global uint* scratch_triangles,
                             __global double* scratch_bounds, __global uint* scratch_triangle_slots,
                             __global uint* scratch_vertex_slots, __global uint* scratch_vertices,
                             __global uint* scratch_corner_rows, __global double* scratch_ways,
                             __global float* scratch_nearest, __global float* scratch_table,
                             __global planar_source* scratch_planar, __global uint* scratch_near,
                             __global cavity_found* found) {
  const uint k = (uint)get_global_id(0);
  if (k >= count) return;
  const cavity_task task = tasks[k];
  cavity_surface mesh;
  mesh.positions = positions;
  mesh.triangles = corners;
  mesh.fan_start = fan_start;
  mesh.fans = fans;
  cavity_particles particles;
  particles.points = points;
  particles.entries = entries;
  particles.ball_start = ball_start;
  particles.ball_size = ball_size;
  cavity c;
  c.triangle = point_triangles[task.particle];
  c.at = points[task.particle];
  c.region = lists + task.region_start;
  c.region_size = task.region_size;
  c.near = lists + task.near_start;
  c.near_size = task.near_size;
  c.further = lists + task.further_start;
  c.further_size = task.further_size;
  cavity_scratch s;
  s.triangles = scratch_triangles + task.triangles_at;
  s.bounds = scratch_bounds + task.triangles_at;
  s.triangle_slots = scratch_triangle_slots + task.triangle_slots_at;
  s.vertex_slots = scratch_vertex_slots + task.vertex_slots_at;
  s.vertices = scratch_vertices + task.corners_at;
  s.corner_rows = scratch_corner_rows + task.corners_at;
  s.ways = scratch_ways + task.corners_at;
  s.nearest = scratch_nearest + task.corners_at;
  s.table = scratch_table + task.table_at;
  s.planar = scratch_planar + task.sources_at;
  s.near = scratch_near + task.sources_at;
  found[k] = cavity_centre(mesh, particles, c, s, cavity_scratch_sizes(mesh, c));
}

#endif
