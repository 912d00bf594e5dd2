#pragma once
// The naive and tiled OpenCL backends: one class, the kernel is the
// difference. The distance table and the mesh's one-rings live on the device;
// positions stay there between iterations, and only the moved count and the
// per-particle energies come back each iteration.
#include "backends/update_kernel.hpp"
#include "common/user_error.hpp"
#include "geodesics/distance_table.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

// A size the device or the compiled kernel cannot take: the sweep reports it
// as skipped, a run as an error.
class LimitExceeded : public UserError {
 public:
  using UserError::UserError;
};

// Throws LimitExceeded naming the limit when the device cannot run `kernel`
// at its sizes (maximum work-group size, local memory); no compilation needed.
void check_device_limits(const DeviceDescription& device, const UpdateKernel& kernel);

class DeviceBackend : public ParticleBackend {
 public:
  // Refuses a work-group size or tile size the device or the compiled kernel
  // cannot take (LimitExceeded), a table it cannot hold and a kernel that does
  // not build (UserError).
  DeviceBackend(const DeviceDescription& device, const SurfaceMesh& mesh, const DistanceTable& distances,
                const EnergyParams& energy, const UpdateKernel& kernel);

  std::string device_name() const override { return device_name_; }
  void set_positions(std::span<const VertexId> positions) override;
  std::vector<VertexId> positions() override;
  // Sequential is the serial reference's alone: UserError here.
  IterationStats iterate(Scheme scheme, unsigned colors) override;
  double total_energy() override;

  // The vertex each particle of the last sub-step chose, before collisions
  // were resolved (for tests: what the update kernel itself decided).
  std::vector<VertexId> last_choices();

  // Measurement without side effects, for sweep and bench. Neither moves a
  // particle, so repeated calls do identical work.
  // The vertex every particle chooses in one synchronous step (one launch).
  std::vector<VertexId> synchronous_choices();
  // The update kernels of one iteration of `scheme`: device milliseconds
  // from profiling events.
  double time_update_kernels(Scheme scheme, unsigned colors);

 private:
  // Enqueues the update kernel for the particles of `color`.
  cl::Event enqueue_update(cl_uint color, cl_uint colors, cl_uint particles);

  std::string device_name_;
  UpdateKernel kernel_;
  cl_uint vertex_count_;
  cl_uint particle_count_ = 0;
  cl::Context context_;
  cl::CommandQueue queue_;
  cl::Kernel update_;
  cl::Kernel claim_targets_;
  cl::Kernel apply_moves_;
  cl::Kernel particle_energies_;
  cl::Buffer distances_;
  cl::Buffer ring_offsets_;
  cl::Buffer ring_neighbors_;
  cl::Buffer positions_;
  cl::Buffer chosen_;
  cl::Buffer claims_;  // per vertex: the smallest index that chose it
  cl::Buffer moved_count_;
  cl::Buffer energies_;
};

}  // namespace meshparticles
