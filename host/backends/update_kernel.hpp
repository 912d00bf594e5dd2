#pragma once
// The update kernels as the host sees them (the paper's naive and tiled, and
// the field method's): which file,
// which compile-time parameters, how many work-groups a sub-step launches,
// how much local memory they need. Everything a launch or a size check needs
// to know about a kernel lives here.
#include <cstddef>
#include <string>

#include "opencl/program_builder.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

enum class KernelKind { naive, tiled, field };

KernelKind parse_kernel_kind(const std::string& name);  // "naive" | "tiled" | "field"
std::string kernel_kind_name(KernelKind kind);

struct UpdateKernel {
  KernelKind kind = KernelKind::tiled;
  std::size_t work_group_size = 0;
  std::size_t tile_size = 0;        // tiled only
  std::size_t candidate_slots = 0;  // the mesh's largest valence + 1
  WeightFormat weights = WeightFormat::float32;  // field only

  std::string file() const;         // "tiled_update.cl"
  std::string function() const;     // "tiled_update"
  // The particles one work-group updates (naive: one; field: one per work-item).
  std::size_t particles_per_group() const;
  std::size_t work_groups_for(std::size_t particles) const;
  std::size_t local_memory_bytes() const;
  KernelDefines defines(Potential potential) const;
  // "wg 32 tile 64" (naive: "wg 16"; field: "wg 64", "wg 64 half"), for
  // tables and progress lines.
  std::string sizes_text() const;
};

// Sizes used when neither --wg nor --tile is given (chosen by measurement,
// docs/PERFORMANCE.md), capped to the device's maximum work-group size.
UpdateKernel default_update_kernel(KernelKind kind, std::size_t candidate_slots, std::size_t device_max_work_group);

}  // namespace meshparticles
