#pragma once
// What every OpenCL backend shares: the context and queue, the mesh's
// one-rings, the particle positions (they stay on the device between
// iterations) and the sub-step loop - the update kernel writes and claims
// each particle's choice, apply_moves commits the claimed moves and lists
// them. The subclasses differ in how a choice is computed: by direct sums
// over all particles (naive, tiled: DirectSumBackend) or from an accumulated
// field (FieldBackend).
#include <memory>

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

// Throws UserError (naming the bytes needed, the bytes the device has and
// the vertices that would fit) when the backend's buffers for this mesh and
// n cannot fit on the device: its V x V table against the largest buffer,
// everything against the global memory. Checked before any distance is
// computed and again before anything is allocated. Without `dense_table`
// (the field backend on local distances) there is no table to check here:
// check_local_field_device checks its balls.
void check_device_memory(const DeviceDescription& device, const UpdateKernel& kernel, std::size_t vertex_count,
                         std::size_t edge_count, std::size_t particle_count, bool dense_table = true);

// A profiled command's time on the device.
double device_milliseconds(const cl::Event& event);

class DeviceBackend : public ParticleBackend {
 public:
  std::string device_name() const override { return device_.name; }
  void set_positions(std::span<const VertexId> positions) override;
  std::vector<VertexId> positions() override;
  // Sequential runs one sub-step per particle (n launches of each kernel).
  IterationStats iterate(Scheme scheme, unsigned colors) override;

  // The vertex each particle of the last sub-step chose, before collisions
  // were resolved (for tests: what the update kernel itself decided).
  std::vector<VertexId> last_choices();

  // Measurement without side effects, for sweep and bench. Neither moves a
  // particle, so repeated calls do identical work.
  // The vertex every particle chooses in one synchronous step (one launch).
  std::vector<VertexId> synchronous_choices();
  // The update kernels of one iteration of `scheme`, plus what the backend
  // measures with them (field: one rebuild of F); device milliseconds from
  // profiling events.
  double time_update_kernels(Scheme scheme, unsigned colors);

  std::optional<DeviceTraffic> traffic() const override { return traffic_; }

 protected:
  DeviceBackend(const DeviceDescription& device, const SurfaceMesh& mesh, const UpdateKernel& kernel,
                bool dense_table = true);
  // The backend's one program (its descriptor's files, or `files`;
  // apply_moves.cl among them), from the process's program cache; the
  // commit kernel is taken from it.
  cl::Program program(const DeviceDescription& device, Potential potential);
  cl::Program program(const DeviceDescription& device, Potential potential, const std::vector<std::string>& files);
  // Refuses sizes the compiled kernel cannot take: its work-group limit and
  // its local memory (CL_KERNEL_WORK_GROUP_SIZE, CL_KERNEL_LOCAL_MEM_SIZE).
  void check_kernel_limits(const cl::Kernel& kernel, const DeviceDescription& device) const;
  // A device buffer of `bytes`; an allocation the device refuses is a
  // UserError naming `what`, the bytes and the device's memory.
  cl::Buffer allocate(cl_mem_flags flags, std::size_t bytes, const std::string& what, const void* initial = nullptr);
  // Launches an update kernel whose arguments from `color_arg` on are
  // (color, colors, rank_stacks), over the work-groups `particles` need.
  cl::Event launch_update(cl::Kernel& update, cl_uint color_arg, cl_uint color, cl_uint colors, cl_uint particles,
                          cl_uint rank_stacks);

  // Every launch and every wait for the device goes through these, so a run
  // can say how many an iteration took (traffic()).
  void launch(const cl::Kernel& kernel, const cl::NDRange& global, const cl::NDRange& local = cl::NullRange,
              cl::Event* event = nullptr);
  void read_blocking(const cl::Buffer& buffer, std::size_t offset, std::size_t bytes, void* into);
  void write_blocking(const cl::Buffer& buffer, std::size_t offset, std::size_t bytes, const void* from);
  void wait_for_device();

  // The update kernel for the particles of `color` (rank_stacks 0: the
  // sequential rule, every particle takes its best candidate).
  virtual cl::Event enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) = 0;
  // Called after set_positions has uploaded them: `resized` when the
  // particle count changed, so the per-particle buffers are new.
  virtual void positions_changed(bool resized) = 0;
  // After the moves of `color` were committed; events of kernels that
  // belong in the iteration's kernel time.
  virtual void after_commit(cl_uint /*color*/, cl_uint /*colors*/, std::vector<cl::Event>& /*events*/) {}
  // After a whole iteration (field: the periodic rebuild).
  virtual void after_iteration(std::vector<cl::Event>& /*events*/) {}
  // What time_update_kernels measures beside the update kernels.
  virtual void enqueue_measured_extras(std::vector<cl::Event>& /*events*/) {}

  DeviceDescription device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  UpdateKernel kernel_;
  cl_uint vertex_count_;
  cl_uint particle_count_ = 0;
  cl::Buffer ring_offsets_;
  cl::Buffer ring_neighbors_;
  cl::Buffer positions_;
  cl::Buffer chosen_;
  cl::Buffer claims_;       // per vertex: the smallest index that chose it (claims.h)
  cl::Buffer move_counts_;  // per colour of the iteration
  cl::Buffer moves_;        // per colour: (from, to) of each committed move
  DeviceTraffic traffic_;

 private:
  cl_uint group_count(Scheme scheme, unsigned colors) const;
  void reset_claims();

  cl::Kernel apply_moves_;
};

// The backend whose kernel `kernel` is, made by its descriptor. Throws
// LimitExceeded for sizes the device refuses, UserError for buffers it
// cannot hold or a kernel that does not build.
std::unique_ptr<DeviceBackend> make_device_backend(const DeviceDescription& device, const UpdateKernel& kernel,
                                                   const BackendInputs& inputs);

}  // namespace meshparticles
