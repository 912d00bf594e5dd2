#pragma once
// The paper's two GPU strategies, naive and tiled: each candidate's energy is
// a direct sum over all particles, read from the distance table on the
// device. One class; the kernel is the difference.
#include "backends/device_backend.hpp"

namespace meshparticles {

class DirectSumBackend : public DeviceBackend {
 public:
  // Refuses sizes the device or the compiled kernel cannot take
  // (LimitExceeded), a table it cannot hold and a kernel that does not build
  // (UserError).
  DirectSumBackend(const DeviceDescription& device, const UpdateKernel& kernel, const BackendInputs& inputs);

  double total_energy() override;

 private:
  cl::Event enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) override;
  void positions_changed(bool resized) override;

  cl::Kernel update_;
  cl::Kernel particle_energies_;
  cl::Buffer distances_;
  cl::Buffer energies_;
};

// The descriptors of the paper's GPU1 and GPU2 (backend_table.hpp).
const BackendDescriptor& naive_backend();
const BackendDescriptor& tiled_backend();

}  // namespace meshparticles
