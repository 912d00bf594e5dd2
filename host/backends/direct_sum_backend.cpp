#include "backends/direct_sum_backend.hpp"

#include <algorithm>

namespace meshparticles {

// Arguments of naive_update and tiled_update, in order.
enum DirectSumArg : cl_uint {
  kDirectDistances, kDirectVertexCount, kDirectRingOffsets, kDirectRingNeighbors, kDirectPositions,
  kDirectParticleCount, kDirectColor, kDirectColors, kDirectRankStacks, kDirectInvTwoSigmaSq, kDirectChosen,
  kDirectClaims
};

DirectSumBackend::DirectSumBackend(const DeviceDescription& device, const UpdateKernel& kernel,
                                   const BackendInputs& inputs)
    : DeviceBackend(device, inputs.mesh, kernel) {
  const DistanceTable& distances = dense_table_for(inputs.distances, kernel.name());
  const cl::Program built = program(device, inputs.energy.potential);
  update_ = cl::Kernel(built, kernel.function().c_str());
  particle_energies_ = cl::Kernel(built, "particle_energies");
  check_kernel_limits(update_, device);

  distances_ = allocate(CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, distances.byte_size(), "the distance table",
                        distances.values().data());
  const float inv_two_sigma_sq = float(inputs.energy.inv_two_sigma_sq());
  update_.setArg(kDirectDistances, distances_);
  update_.setArg(kDirectVertexCount, vertex_count_);
  update_.setArg(kDirectRingOffsets, ring_offsets_);
  update_.setArg(kDirectRingNeighbors, ring_neighbors_);
  update_.setArg(kDirectInvTwoSigmaSq, inv_two_sigma_sq);
  update_.setArg(kDirectClaims, claims_);
  particle_energies_.setArg(0, distances_);
  particle_energies_.setArg(1, vertex_count_);
  particle_energies_.setArg(4, inv_two_sigma_sq);
}

void DirectSumBackend::positions_changed(bool resized) {
  if (!resized) return;
  energies_ = allocate(CL_MEM_READ_WRITE, particle_count_ * sizeof(cl_float), "the particle energies");
  update_.setArg(kDirectPositions, positions_);
  update_.setArg(kDirectParticleCount, particle_count_);
  update_.setArg(kDirectChosen, chosen_);
  particle_energies_.setArg(2, positions_);
  particle_energies_.setArg(3, particle_count_);
  particle_energies_.setArg(5, energies_);
}

cl::Event DirectSumBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) {
  return launch_update(update_, kDirectColor, color, colors, particles, rank_stacks);
}

double DirectSumBackend::total_energy() {
  std::vector<float> energies(particle_count_);
  launch(particle_energies_, cl::NDRange(particle_count_));
  read_blocking(energies_, 0, energies.size() * sizeof(float), energies.data());
  double sum = 0;
  for (const float e : energies) sum += e;
  return sum / 2;  // every pair was counted from both ends
}

namespace {

// The direct-sum kernels' __local arrays, in bytes: per candidate slot a
// float energy and a byte of occupancy, per particle a stack rank, and
// (tiled) the tile of staged positions.
std::size_t direct_sum_local_bytes(const UpdateKernel& kernel) {
  const std::size_t particles = kernel.particles_per_group();
  const std::size_t slots = 5 * particles * kernel.candidate_slots + 4 * particles;
  return kernel.spec().takes_tile ? slots + 4 * kernel.tile_size : slots;
}

std::unique_ptr<DeviceBackend> make_direct_sum(const DeviceDescription& device, const UpdateKernel& kernel,
                                               const BackendInputs& inputs) {
  return std::make_unique<DirectSumBackend>(device, kernel, inputs);
}

DeviceKernelSpec direct_sum_spec(const std::string& update_function) {
  DeviceKernelSpec spec;
  spec.update_function = update_function;
  spec.program_files = {update_function + ".cl", "apply_moves.cl", "particle_energies.cl"};
  spec.local_memory_bytes = direct_sum_local_bytes;
  spec.table_bytes_per_entry = [](const UpdateKernel&) { return sizeof(float); };
  spec.make = make_direct_sum;
  return spec;
}

}  // namespace

const BackendDescriptor& naive_backend() {
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = "naive";
    d.summary = "the paper's GPU1: one work-group per particle, each candidate summed over all particles (OpenCL)";
    d.default_scheme = Scheme::monotone;
    d.needs_dense_table = true;
    d.paper_row = PaperRow::gpu1_naive;
    d.device = direct_sum_spec("naive_update");
    // One work-item per candidate, rounded up to a multiple of 8.
    d.device->default_sizes = [](UpdateKernel& kernel, const std::string&) {
      kernel.work_group_size = (kernel.candidate_slots + 7) / 8 * 8;
    };
    d.device->particles_per_group = [](const UpdateKernel&) { return std::size_t{1}; };
    return d;
  }();
  return descriptor;
}

const BackendDescriptor& tiled_backend() {
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = "tiled";
    d.summary = "the paper's GPU2: positions staged in local memory, tile by tile (OpenCL)";
    d.default_scheme = Scheme::monotone;
    d.needs_dense_table = true;
    d.paper_row = PaperRow::gpu2_tiled;
    d.device = direct_sum_spec("tiled_update");
    d.device->takes_tile = true;
    // The best or near-best of repeated sweeps on PoCL at sphere/1024
    // (docs/PERFORMANCE.md); `sweep --save` finds a device's own.
    d.device->default_sizes = [](UpdateKernel& kernel, const std::string&) {
      kernel.work_group_size = 32;
      kernel.tile_size = 64;
    };
    // Mirrors PARTICLES_PER_GROUP in kernels/tiled_update.cl.
    d.device->particles_per_group = [](const UpdateKernel& kernel) {
      return kernel.work_group_size >= kernel.candidate_slots ? kernel.work_group_size / kernel.candidate_slots
                                                              : std::size_t{1};
    };
    return d;
  }();
  return descriptor;
}

}  // namespace meshparticles
