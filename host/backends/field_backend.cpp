#include "backends/field_backend.hpp"

#include <algorithm>

#include "backends/local_device_field_backend.hpp"
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

FieldBackend::FieldBackend(const DeviceDescription& device, const UpdateKernel& kernel, const BackendInputs& inputs)
    : DeviceBackend(device, inputs.mesh, kernel), rebuild_every_(inputs.rebuild_every) {
  const DistanceTable& distances = dense_table_for(inputs.distances, kernel.name());
  const cl::Program built = program(device, inputs.energy.potential);
  update_ = cl::Kernel(built, kernel.function().c_str());
  rebuild_ = cl::Kernel(built, "field_rebuild");
  apply_to_field_ = cl::Kernel(built, "field_apply_moves");
  particle_energies_ = cl::Kernel(built, "field_energies");
  for (const cl::Kernel* launched : {&update_, &rebuild_, &apply_to_field_}) check_kernel_limits(*launched, device);

  compute_weight_table(built, distances, inputs.energy);
  field_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_long), "the field");
  occupancy_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_uint), "the occupancy");

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

// W on the device: the distances are uploaded once and turned into weights,
// in place for float32; for half, into a second buffer, after which the
// distances' buffer is released. A 2-D launch, rows by columns: V^2 items in
// one dimension would pass 2^32 at V = 65,536.
void FieldBackend::compute_weight_table(const cl::Program& program, const DistanceTable& distances,
                                        const EnergyParams& energy) {
  cl::Buffer table = allocate(CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, distances.byte_size(), "the distance table",
                              distances.values().data());
  cl::Kernel kernel(program, "weight_table");
  kernel.setArg(0, table);
  kernel.setArg(1, vertex_count_);
  kernel.setArg(2, float(energy.inv_two_sigma_sq()));
  if (kernel_.weights == WeightFormat::float32) {
    weights_ = table;
  } else {
    weights_ = allocate(CL_MEM_READ_WRITE, distances.values().size() * sizeof(cl_half), "the half weight table");
    kernel.setArg(3, weights_);
  }
  const std::size_t columns_per_group = std::min<std::size_t>(64, device_.max_work_group_size);
  const std::size_t columns = (vertex_count_ + columns_per_group - 1) / columns_per_group * columns_per_group;
  queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(columns, vertex_count_),
                              cl::NDRange(columns_per_group, 1));
  queue_.finish();
}

void FieldBackend::positions_changed(bool resized) {
  if (resized) {
    if (particle_count_ > kMaxFieldParticles) {
      throw UserError("the field backend takes at most " + std::to_string(kMaxFieldParticles) + " particles (" +
                      std::to_string(particle_count_) + " asked): its 64-bit field would overflow");
    }
    energies_ = allocate(CL_MEM_READ_WRITE, particle_count_ * sizeof(cl_long), "the particle energies");
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

std::vector<float> FieldBackend::weights() {
  const std::size_t entries = std::size_t(vertex_count_) * vertex_count_;
  std::vector<float> widened(entries);
  if (kernel_.weights == WeightFormat::float32) {
    queue_.enqueueReadBuffer(weights_, CL_TRUE, 0, entries * sizeof(float), widened.data());
    return widened;
  }
  std::vector<_Float16> stored(entries);
  queue_.enqueueReadBuffer(weights_, CL_TRUE, 0, entries * sizeof(cl_half), stored.data());
  for (std::size_t i = 0; i < entries; ++i) widened[i] = float(stored[i]);
  return widened;
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

const BackendDescriptor& field_backend() {
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = "field";
    d.summary = "candidate energies from an accumulated field: the same choices, two reads per candidate (OpenCL)";
    d.field_method = true;
    d.default_scheme = Scheme::monotone;
    d.paper_row = PaperRow::gpu2_tiled;  // beside the paper's fastest
    DeviceKernelSpec& spec = d.device.emplace();
    spec.update_function = "field_update";
    spec.program_files = {"field_weights.cl", "field_accumulate.cl", "field_update.cl", "apply_moves.cl"};
    spec.takes_weight_format = true;
    // wg 8 - 32 were best or near best in three sweeps on PoCL at
    // sphere/1024, larger groups leave the cores idle (V / 8 work-items);
    // 32 is also one NVIDIA warp (docs/PERFORMANCE.md).
    spec.default_sizes = [](UpdateKernel& kernel) { kernel.work_group_size = 32; };
    spec.particles_per_group = [](const UpdateKernel& kernel) { return kernel.work_group_size; };
    // Each work-item keeps its candidates in private memory: no __local.
    spec.local_memory_bytes = [](const UpdateKernel&) { return std::size_t{0}; };
    // float32 W takes over the distances' buffer; half W coexists with it
    // until it is computed.
    spec.table_bytes_per_entry = [](const UpdateKernel& kernel) {
      return kernel.weights == WeightFormat::half ? sizeof(float) + sizeof(cl_half) : sizeof(float);
    };
    spec.make = [](const DeviceDescription& device, const UpdateKernel& kernel,
                   const BackendInputs& inputs) -> std::unique_ptr<DeviceBackend> {
      if (const LocalDistances* balls = inputs.distances.local_balls()) {
        return std::make_unique<LocalDeviceFieldBackend>(device, kernel, inputs, *balls);
      }
      return std::make_unique<FieldBackend>(device, kernel, inputs);
    };
    return d;
  }();
  return descriptor;
}

}  // namespace meshparticles
