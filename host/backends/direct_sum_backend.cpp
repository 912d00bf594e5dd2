#include "backends/direct_sum_backend.hpp"

#include <algorithm>

#include "geodesics/memory_guard.hpp"

namespace meshparticles {

// Arguments of naive_update and tiled_update, in order.
enum UpdateArg : cl_uint {
  kDistances, kVertexCount, kRingOffsets, kRingNeighbors, kPositions, kParticleCount, kColor, kColors,
  kRankStacks, kInvTwoSigmaSq, kChosen, kClaims
};

DirectSumBackend::DirectSumBackend(const DeviceDescription& device, const SurfaceMesh& mesh,
                                   const DistanceTable& distances, const EnergyParams& energy,
                                   const UpdateKernel& kernel)
    : DeviceBackend(device, mesh, kernel) {
  check_distance_table_fits(mesh.vertex_count(), device.max_allocation_bytes,
                            "the largest buffer " + device.name + " allows");
  const cl::Program program = build_program(context_, device.device,
                                            {kernel.file(), "apply_moves.cl", "particle_energies.cl"},
                                            kernel.defines(energy.potential));
  attach_commit_kernel(program);
  update_ = cl::Kernel(program, kernel.function().c_str());
  particle_energies_ = cl::Kernel(program, "particle_energies");
  check_kernel_limits(update_, device);

  distances_ = cl::Buffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, distances.values().size() * sizeof(float),
                          const_cast<float*>(distances.values().data()));
  const float inv_two_sigma_sq = float(energy.inv_two_sigma_sq());
  update_.setArg(kDistances, distances_);
  update_.setArg(kVertexCount, vertex_count_);
  update_.setArg(kRingOffsets, ring_offsets_);
  update_.setArg(kRingNeighbors, ring_neighbors_);
  update_.setArg(kInvTwoSigmaSq, inv_two_sigma_sq);
  update_.setArg(kClaims, claims_);
  particle_energies_.setArg(0, distances_);
  particle_energies_.setArg(1, vertex_count_);
  particle_energies_.setArg(4, inv_two_sigma_sq);
}

void DirectSumBackend::positions_changed(bool resized) {
  if (!resized) return;
  energies_ = cl::Buffer(context_, CL_MEM_READ_WRITE, std::max<std::size_t>(1, particle_count_) * sizeof(cl_float));
  update_.setArg(kPositions, positions_);
  update_.setArg(kParticleCount, particle_count_);
  update_.setArg(kChosen, chosen_);
  particle_energies_.setArg(2, positions_);
  particle_energies_.setArg(3, particle_count_);
  particle_energies_.setArg(5, energies_);
}

cl::Event DirectSumBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) {
  return launch_update(update_, kColor, color, colors, particles, rank_stacks);
}

double DirectSumBackend::total_energy() {
  std::vector<float> energies(particle_count_);
  queue_.enqueueNDRangeKernel(particle_energies_, cl::NullRange, cl::NDRange(particle_count_));
  queue_.enqueueReadBuffer(energies_, CL_TRUE, 0, energies.size() * sizeof(float), energies.data());
  double sum = 0;
  for (const float e : energies) sum += e;
  return sum / 2;  // every pair was counted from both ends
}

}  // namespace meshparticles
