#pragma once
// The naive and tiled OpenCL backends: one class, the kernel is the
// difference. The distance table and the mesh's one-rings live on the device;
// positions stay there between iterations, and only the moved count and the
// per-particle energies come back each iteration.
#include "backends/update_kernel.hpp"
#include "geodesics/distance_table.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

// Throws UserError naming the limit when the device cannot run `kernel` at
// its sizes (maximum work-group size, local memory); no compilation needed.
void check_device_limits(const DeviceDescription& device, const UpdateKernel& kernel);

class DeviceBackend : public ParticleBackend {
 public:
  // Refuses (UserError naming the limit) a work-group size, tile size or
  // table the device cannot take, and a kernel that does not build.
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

 private:
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
