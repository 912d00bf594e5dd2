#include "backends/update_kernel.hpp"

#include <algorithm>

#include "common/user_error.hpp"

namespace meshparticles {

KernelKind parse_kernel_kind(const std::string& name) {
  if (name == "naive") return KernelKind::naive;
  if (name == "tiled") return KernelKind::tiled;
  if (name == "field") return KernelKind::field;
  throw UserError("unknown kernel '" + name + "' (choose naive, tiled or field)");
}

std::string kernel_kind_name(KernelKind kind) {
  switch (kind) {
    case KernelKind::naive: return "naive";
    case KernelKind::tiled: return "tiled";
    case KernelKind::field: return "field";
  }
  return "?";
}

std::string UpdateKernel::file() const { return function() + ".cl"; }

std::string UpdateKernel::function() const { return kernel_kind_name(kind) + "_update"; }

// Mirrors PARTICLES_PER_GROUP in kernels/tiled_update.cl.
std::size_t UpdateKernel::particles_per_group() const {
  if (kind == KernelKind::naive) return 1;
  if (kind == KernelKind::field) return work_group_size;
  return work_group_size >= candidate_slots ? work_group_size / candidate_slots : 1;
}

std::size_t UpdateKernel::work_groups_for(std::size_t particles) const {
  const std::size_t per_group = particles_per_group();
  return (particles + per_group - 1) / per_group;
}

// The __local arrays of each kernel, in bytes: naive and tiled, per
// candidate slot a float energy and a byte of occupancy, per particle a stack
// rank, and the tile. field keeps its scratch in private memory: none.
std::size_t UpdateKernel::local_memory_bytes() const {
  if (kind == KernelKind::field) return 0;
  const std::size_t particles = particles_per_group();
  const std::size_t slots = 5 * particles * candidate_slots + 4 * particles;
  return kind == KernelKind::naive ? slots : slots + 4 * tile_size;
}

KernelDefines UpdateKernel::defines(Potential potential) const {
  KernelDefines defines{{"WORK_GROUP_SIZE", (long long)work_group_size},
                        {"CANDIDATE_SLOTS", (long long)candidate_slots},
                        {"POTENTIAL_GAUSS", potential == Potential::gauss ? 1 : 0}};
  if (kind == KernelKind::tiled) defines["TILE_SIZE"] = (long long)tile_size;
  if (kind == KernelKind::field) defines["WEIGHTS_HALF"] = weights == WeightFormat::half ? 1 : 0;
  return defines;
}

std::string UpdateKernel::sizes_text() const {
  std::string text = "wg " + std::to_string(work_group_size);
  if (kind == KernelKind::tiled) text += " tile " + std::to_string(tile_size);
  if (kind == KernelKind::field && weights == WeightFormat::half) text += " half";
  return text;
}

UpdateKernel default_update_kernel(KernelKind kind, std::size_t candidate_slots, std::size_t device_max_work_group) {
  UpdateKernel kernel;
  kernel.kind = kind;
  kernel.candidate_slots = candidate_slots;
  if (kind == KernelKind::naive) {
    // One work-item per candidate, rounded up to a multiple of 8.
    kernel.work_group_size = (candidate_slots + 7) / 8 * 8;
  } else if (kind == KernelKind::tiled) {
    // The best or near-best of repeated sweeps on PoCL at sphere/1024
    // (docs/PERFORMANCE.md); `sweep --save` finds a device's own.
    kernel.work_group_size = 32;
    kernel.tile_size = 64;
  } else {
    // Field: wg 8 - 32 were best or near best in three sweeps on PoCL at
    // sphere/1024, larger groups leave the cores idle (V / 8 work-items);
    // 32 is also one NVIDIA warp (docs/PERFORMANCE.md).
    kernel.work_group_size = 32;
  }
  kernel.work_group_size = std::max<std::size_t>(1, std::min(kernel.work_group_size, device_max_work_group));
  return kernel;
}

}  // namespace meshparticles
