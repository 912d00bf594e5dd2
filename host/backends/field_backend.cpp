#include "backends/field_backend.hpp"

#include <algorithm>

#include "geodesics/memory_guard.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

// Arguments of field_update, in order.
enum UpdateArg : cl_uint {
  kField, kWeights, kVertexCount, kRingOffsets, kRingNeighbors, kOccupancy, kPositions, kParticleCount, kColor,
  kColors, kRankStacks, kChosen, kClaims
};
// Arguments of field_apply_moves, in order (field_rebuild takes the first four
// of them, then field and occupancy).
enum ApplyArg : cl_uint {
  kApplyWeights, kApplyVertexCount, kApplyPositions, kApplyParticleCount, kApplyColor, kApplyColors,
  kApplyMoveCounts, kApplyMoves, kApplyField, kApplyOccupancy
};

namespace {

// W on the device: the distances are uploaded once and turned into weights,
// in place for float32; for half, into a second buffer, after which the
// distances' buffer is released.
cl::Buffer weight_table(const cl::Context& context, const cl::CommandQueue& queue, const cl::Program& program,
                        const DistanceTable& distances, const EnergyParams& energy, WeightFormat format) {
  const std::size_t entries = distances.values().size();
  cl::Buffer table(context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, entries * sizeof(float),
                   const_cast<float*>(distances.values().data()));
  cl::Kernel kernel(program, "weight_table");
  const float inv_two_sigma_sq = float(energy.inv_two_sigma_sq());
  if (format == WeightFormat::float32) {
    kernel.setArg(0, table);
    kernel.setArg(1, inv_two_sigma_sq);
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(entries));
    queue.finish();
    return table;
  }
  cl::Buffer weights(context, CL_MEM_READ_WRITE, entries * sizeof(cl_half));
  kernel.setArg(0, table);
  kernel.setArg(1, inv_two_sigma_sq);
  kernel.setArg(2, weights);
  queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(entries));
  queue.finish();
  return weights;
}

}  // namespace

FieldBackend::FieldBackend(const DeviceDescription& device, const SurfaceMesh& mesh, const DistanceTable& distances,
                           const EnergyParams& energy, const UpdateKernel& kernel, std::size_t rebuild_every)
    : DeviceBackend(device, mesh, kernel), rebuild_every_(rebuild_every) {
  check_distance_table_fits(mesh.vertex_count(), device.max_allocation_bytes,
                            "the largest buffer " + device.name + " allows");
  const cl::Program program =
      build_program(context_, device.device,
                    {"field_weights.cl", "field_accumulate.cl", kernel.file(), "apply_moves.cl"},
                    kernel.defines(energy.potential));
  attach_commit_kernel(program);
  update_ = cl::Kernel(program, kernel.function().c_str());
  rebuild_ = cl::Kernel(program, "field_rebuild");
  apply_to_field_ = cl::Kernel(program, "field_apply_moves");
  particle_energies_ = cl::Kernel(program, "field_energies");
  for (const cl::Kernel* launched : {&update_, &rebuild_, &apply_to_field_}) check_kernel_limits(*launched, device);

  weights_ = weight_table(context_, queue_, program, distances, energy, kernel.weights);
  field_ = cl::Buffer(context_, CL_MEM_READ_WRITE, mesh.vertex_count() * sizeof(cl_long));
  occupancy_ = cl::Buffer(context_, CL_MEM_READ_WRITE, mesh.vertex_count() * sizeof(cl_uint));

  update_.setArg(kField, field_);
  update_.setArg(kWeights, weights_);
  update_.setArg(kVertexCount, vertex_count_);
  update_.setArg(kRingOffsets, ring_offsets_);
  update_.setArg(kRingNeighbors, ring_neighbors_);
  update_.setArg(kOccupancy, occupancy_);
  update_.setArg(kClaims, claims_);
  for (cl::Kernel* kernel_per_vertex : {&rebuild_, &apply_to_field_}) {
    kernel_per_vertex->setArg(kApplyWeights, weights_);
    kernel_per_vertex->setArg(kApplyVertexCount, vertex_count_);
  }
  rebuild_.setArg(4, field_);
  rebuild_.setArg(5, occupancy_);
  apply_to_field_.setArg(kApplyField, field_);
  apply_to_field_.setArg(kApplyOccupancy, occupancy_);
  particle_energies_.setArg(0, weights_);
  particle_energies_.setArg(1, vertex_count_);
  particle_energies_.setArg(4, field_);
}

void FieldBackend::positions_changed(bool resized) {
  if (resized) {
    if (particle_count_ > kMaxFieldParticles) {
      throw UserError("the field backend takes at most " + std::to_string(kMaxFieldParticles) + " particles (" +
                      std::to_string(particle_count_) + " asked): its 64-bit field would overflow");
    }
    energies_ = cl::Buffer(context_, CL_MEM_READ_WRITE, std::max<std::size_t>(1, particle_count_) * sizeof(cl_long));
    update_.setArg(kPositions, positions_);
    update_.setArg(kParticleCount, particle_count_);
    update_.setArg(kChosen, chosen_);
    for (cl::Kernel* kernel_per_vertex : {&rebuild_, &apply_to_field_}) {
      kernel_per_vertex->setArg(kApplyPositions, positions_);
      kernel_per_vertex->setArg(kApplyParticleCount, particle_count_);
    }
    apply_to_field_.setArg(kApplyMoveCounts, move_counts_);
    apply_to_field_.setArg(kApplyMoves, moves_);
    particle_energies_.setArg(2, positions_);
    particle_energies_.setArg(3, particle_count_);
    particle_energies_.setArg(5, energies_);
  }
  iterations_ = 0;
  enqueue_rebuild();
}

// One work-item per VERTICES_PER_ITEM (8) vertices (kernels/field_accumulate.cl).
cl::NDRange FieldBackend::vertex_range() const {
  const std::size_t items = (vertex_count_ + 7) / 8, group = kernel_.work_group_size;
  return cl::NDRange((items + group - 1) / group * group);
}

cl::Event FieldBackend::enqueue_rebuild() {
  cl::Event event;
  queue_.enqueueNDRangeKernel(rebuild_, cl::NullRange, vertex_range(), cl::NDRange(kernel_.work_group_size),
                              nullptr, &event);
  return event;
}

void FieldBackend::rebuild_field() {
  enqueue_rebuild();
  queue_.finish();
}

std::vector<std::int64_t> FieldBackend::field() {
  std::vector<std::int64_t> field(vertex_count_);
  queue_.enqueueReadBuffer(field_, CL_TRUE, 0, field.size() * sizeof(cl_long), field.data());
  return field;
}

cl::Event FieldBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) {
  return launch_update(update_, kColor, color, colors, particles, rank_stacks);
}

void FieldBackend::after_commit(cl_uint color, cl_uint colors, std::vector<cl::Event>& events) {
  apply_to_field_.setArg(kApplyColor, color);
  apply_to_field_.setArg(kApplyColors, colors);
  cl::Event event;
  queue_.enqueueNDRangeKernel(apply_to_field_, cl::NullRange, vertex_range(), cl::NDRange(kernel_.work_group_size),
                              nullptr, &event);
  events.push_back(event);
}

void FieldBackend::after_iteration(std::vector<cl::Event>& events) {
  ++iterations_;
  if (rebuild_every_ > 0 && iterations_ % rebuild_every_ == 0) events.push_back(enqueue_rebuild());
}

// A rebuild streams n rows: what an iteration's field updates cost when half
// the particles move (each move is two rows).
void FieldBackend::enqueue_measured_extras(std::vector<cl::Event>& events) { events.push_back(enqueue_rebuild()); }

double FieldBackend::total_energy() {
  std::vector<std::int64_t> energies(particle_count_);
  queue_.enqueueNDRangeKernel(particle_energies_, cl::NullRange, cl::NDRange(particle_count_));
  queue_.enqueueReadBuffer(energies_, CL_TRUE, 0, energies.size() * sizeof(cl_long), energies.data());
  double sum = 0;
  for (const std::int64_t units : energies) sum += double(units);
  return sum / (2.0 * double(kFieldUnitsPerWeight));  // every pair was counted from both ends
}

}  // namespace meshparticles
