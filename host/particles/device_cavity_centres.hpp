#pragma once
// The centres of the cavities of one independent set of spread's evening
// on an OpenCL device (kernels/cavity_centres.cl, one work-item a
// particle): the same code as the host's (kernels/cavity_centre.h), built
// without unsafe math and with FP_CONTRACT off, so the same bits as
// particles/cavity_centre on any device with double precision.
//
// The surface's buffers stay on the device for the object's life; the
// balls are sent as they grow (ParticleBalls puts a new ball at its end),
// the particles' points and the set's lists each call.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "opencl/device_discovery.hpp"
#include "opencl/growing_buffer.hpp"
#include "opencl/opencl.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"
#include "particles/cavity_centre.hpp"

namespace meshparticles {

// Whether `device` computes in double precision (cl_khr_fp64, or OpenCL
// 2.0's optional double support), which the kernel needs.
bool device_has_double_precision(const DeviceDescription& device);

class DeviceCavityCentres {
 public:
  struct Statistics {
    std::size_t launches = 0;  // one a set (or more, where its scratch needs)
    std::size_t cavities = 0;
    std::size_t sets_on_host = 0;  // sets left to the host: the balls outgrew the device's largest buffer
    double seconds = 0;  // everything: uploads, the kernel, the read
  };

  // Throws UserError when `device` has no double precision.
  DeviceCavityCentres(const SurfaceMesh& mesh, const DeviceDescription& device);

  // The centre of each cavity of `cavities` (cavities[k] particle
  // particles[k]'s), in their order, as cavity_centre gives it on the
  // host: the particles standing at `points`, in triangles `triangles`,
  // their balls `balls`. None where the balls outgrow the device's largest
  // buffer: the host's centres are the same bits.
  std::optional<std::vector<CavityCentre>> centres(std::span<const std::uint32_t> particles, const std::vector<Cavity>& cavities,
                                    const std::vector<vec3d>& points, const std::vector<std::uint32_t>& triangles,
                                    const ParticleBalls& balls);

  const std::string& device_name() const { return device_name_; }
  const Statistics& statistics() const { return statistics_; }

 private:
  // balls' entries brought up to date on the device: the new ones only,
  // unless the buffer is too small or the balls were compacted.
  void send_balls(const ParticleBalls& balls);
  // `buffer` with room for `bytes` on this device; whether it was made anew.
  bool fit(GrowingBuffer& buffer, std::size_t bytes);

  const VertexTriangles fans_;
  const CavitySurface surface_;  // the mesh as cavity_centre reads it, sent once
  std::string device_name_;
  cl_ulong max_allocation_bytes_ = 0;
  std::size_t work_group_size_ = 1;
  cl::Context context_;
  cl::CommandQueue queue_;
  cl::Kernel kernel_;
  cl::Buffer positions_, corners_, fan_start_, fan_triangles_;
  // Made anew only when a call needs more: the balls, the calls' inputs,
  // scratch and results.
  GrowingBuffer entries_;
  std::size_t entries_sent_ = 0, compactions_seen_ = 0;  // of balls' entries: how many are on the device
  GrowingBuffer tasks_, lists_, triangles_, points_, ball_start_, ball_size_, found_;
  GrowingBuffer scratch_triangles_, scratch_bounds_, scratch_triangle_slots_, scratch_vertex_slots_, scratch_vertices_, scratch_corner_rows_, scratch_ways_,
      scratch_nearest_, scratch_table_, scratch_planar_, scratch_near_;
  Statistics statistics_;
};

}  // namespace meshparticles
