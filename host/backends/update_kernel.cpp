#include "backends/update_kernel.hpp"

#include <algorithm>

#include "particles/potentials.hpp"

namespace meshparticles {

std::string UpdateKernel::file() const { return function() + ".cl"; }

std::size_t UpdateKernel::work_groups_for(std::size_t particles) const {
  const std::size_t per_group = particles_per_group();
  return (particles + per_group - 1) / per_group;
}

KernelDefines UpdateKernel::defines(Potential potential) const {
  KernelDefines defines{{"WORK_GROUP_SIZE", (long long)work_group_size},
                        {"CANDIDATE_SLOTS", (long long)candidate_slots},
                        {"POTENTIAL_GAUSS", potential_spec(potential).kernel_define}};
  if (spec().takes_tile) defines["TILE_SIZE"] = (long long)tile_size;
  if (spec().takes_weight_format) defines["WEIGHTS_HALF"] = weights == WeightFormat::half ? 1 : 0;
  return defines;
}

std::string UpdateKernel::sizes_text() const {
  std::string text = "wg " + std::to_string(work_group_size);
  if (spec().takes_tile) text += " tile " + std::to_string(tile_size);
  if (weights == WeightFormat::half) text += " half";
  return text;
}

UpdateKernel default_update_kernel(const BackendDescriptor& backend, std::size_t candidate_slots,
                                   std::size_t device_max_work_group, const std::string& device_type) {
  UpdateKernel kernel;
  kernel.backend = &backend;
  kernel.candidate_slots = candidate_slots;
  kernel.spec().default_sizes(kernel, device_type);
  kernel.work_group_size = std::max<std::size_t>(1, std::min(kernel.work_group_size, device_max_work_group));
  return kernel;
}

}  // namespace meshparticles
