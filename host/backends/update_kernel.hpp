#pragma once
// A device backend's update kernel at given sizes, as the host sees it:
// which file and function, which compile-time defines, how many work-groups a
// sub-step launches, how much local memory it needs. What differs between
// kernels comes from their descriptor's DeviceKernelSpec; this is the one
// place the host reads it.
#include <cstddef>
#include <string>

#include "backends/backend_descriptor.hpp"
#include "opencl/program_builder.hpp"

namespace meshparticles {

struct UpdateKernel {
  const BackendDescriptor* backend = nullptr;  // a device backend
  std::size_t work_group_size = 0;
  std::size_t tile_size = 0;        // kernels that take a tile
  std::size_t candidate_slots = 0;  // the mesh's largest valence + 1
  WeightFormat weights = WeightFormat::float32;  // kernels that take a weight format

  const DeviceKernelSpec& spec() const { return *backend->device; }
  const std::string& name() const { return backend->name; }  // "tiled"
  std::string file() const;                                  // "tiled_update.cl"
  const std::string& function() const { return spec().update_function; }
  std::size_t particles_per_group() const { return spec().particles_per_group(*this); }
  std::size_t work_groups_for(std::size_t particles) const;
  std::size_t local_memory_bytes() const { return spec().local_memory_bytes(*this); }
  KernelDefines defines(Potential potential) const;
  // "wg 32 tile 64" ("wg 16"; "wg 64 half"), for tables and progress lines.
  std::string sizes_text() const;
};

// The built-in sizes of `backend`'s kernel on a device of `device_type`
// (chosen by measurement, docs/PERFORMANCE.md), capped to the device's
// maximum work-group size.
UpdateKernel default_update_kernel(const BackendDescriptor& backend, std::size_t candidate_slots,
                                   std::size_t device_max_work_group, const std::string& device_type = "CPU");

}  // namespace meshparticles
