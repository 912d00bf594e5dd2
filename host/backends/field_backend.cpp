#include "backends/field_backend.hpp"

#include <algorithm>
#include <limits>

#include "backends/local_device_field_backend.hpp"
#include "common/half_float.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

// Arguments of field_update, in order.
enum FieldUpdateArg : cl_uint {
  kField, kWeights, kVertexCount, kRingOffsets, kRingNeighbors, kOccupancy, kPositions, kParticleCount, kColor,
  kColors, kRankStacks, kChosen, kClaims
};
// Arguments of field_apply_moves, in order (field_rebuild takes the first four
// of them, then field and occupancy).
// Arguments of field_iterations, in order.
enum IterationsArg : cl_uint {
  kItField, kItWeights, kItVertexCount, kItRingOffsets, kItRingNeighbors, kItOccupancy, kItPositions,
  kItParticleCount, kItColors, kItMonotone, kItIterations, kItChosen, kItClaims, kItMoveCounts, kItMoves,
  kItStartPositions, kItHistory
};
// field_iterations' history: two words, then these per iteration.
constexpr std::size_t kHistoryHead = 2, kHistoryWords = 4;
constexpr cl_ulong kKeptSequential = 0, kKeptNone = 0xffffffffULL;
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
  one_launch_kernel_ = cl::Kernel(built, "field_iterations");
  for (const cl::Kernel* launched : {&update_, &rebuild_, &apply_to_field_}) check_kernel_limits(*launched, device);
  // One launch needs the whole work-group in one kernel that holds more state.
  one_launch_ =
      kernel_.work_group_size <= one_launch_kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device.device);

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
  one_launch_kernel_.setArg(kItField, field_);
  one_launch_kernel_.setArg(kItWeights, weights_);
  one_launch_kernel_.setArg(kItVertexCount, vertex_count_);
  one_launch_kernel_.setArg(kItRingOffsets, ring_offsets_);
  one_launch_kernel_.setArg(kItRingNeighbors, ring_neighbors_);
  one_launch_kernel_.setArg(kItOccupancy, occupancy_);
  one_launch_kernel_.setArg(kItClaims, claims_);
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
  launch(kernel, cl::NDRange(columns, vertex_count_), cl::NDRange(columns_per_group, 1));
  wait_for_device();
}

void FieldBackend::positions_changed(bool resized) {
  if (resized) {
    check_field_particle_count(particle_count_);
    energies_ = allocate(CL_MEM_READ_WRITE, particle_count_ * sizeof(cl_long), "the particle energies");
    update_.setArg(kPositions, positions_);
    update_.setArg(kParticleCount, particle_count_);
    update_.setArg(kChosen, chosen_);
    for (cl::Kernel* kernel_per_vertex : {&rebuild_, &apply_to_field_}) {
      kernel_per_vertex->setArg(kApplyPositions, positions_);
      kernel_per_vertex->setArg(kApplyParticleCount, particle_count_);
    }
    start_positions_ = allocate(CL_MEM_READ_WRITE, std::max<std::size_t>(1, particle_count_) * sizeof(cl_uint),
                                "the attempts' start positions");
    one_launch_kernel_.setArg(kItPositions, positions_);
    one_launch_kernel_.setArg(kItParticleCount, particle_count_);
    one_launch_kernel_.setArg(kItChosen, chosen_);
    one_launch_kernel_.setArg(kItMoveCounts, move_counts_);
    one_launch_kernel_.setArg(kItMoves, moves_);
    one_launch_kernel_.setArg(kItStartPositions, start_positions_);
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
  launch(rebuild_, vertex_range(), cl::NDRange(kernel_.work_group_size), &event);
  return event;
}

void FieldBackend::rebuild_field() {
  enqueue_rebuild();
  wait_for_device();
}

std::vector<float> FieldBackend::weights() {
  const std::size_t entries = std::size_t(vertex_count_) * vertex_count_;
  std::vector<float> widened(entries);
  if (kernel_.weights == WeightFormat::float32) {
    read_blocking(weights_, 0, entries * sizeof(float), widened.data());
    return widened;
  }
  std::vector<cl_half> stored(entries);
  read_blocking(weights_, 0, entries * sizeof(cl_half), stored.data());
  for (std::size_t i = 0; i < entries; ++i) widened[i] = float_from_half_bits(stored[i]);
  return widened;
}

std::vector<std::int64_t> FieldBackend::field() {
  std::vector<std::int64_t> field(vertex_count_);
  read_blocking(field_, 0, field.size() * sizeof(cl_long), field.data());
  return field;
}

cl::Event FieldBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) {
  return launch_update(update_, kColor, color, colors, particles, rank_stacks);
}

void FieldBackend::after_commit(cl_uint color, cl_uint colors, std::vector<cl::Event>& events) {
  apply_to_field_.setArg(kApplyColor, color);
  apply_to_field_.setArg(kApplyColors, colors);
  cl::Event event;
  launch(apply_to_field_, vertex_range(), cl::NDRange(kernel_.work_group_size), &event);
  events.push_back(event);
}

void FieldBackend::after_iteration(std::vector<cl::Event>& events) {
  ++iterations_;
  if (rebuild_every_ > 0 && iterations_ % rebuild_every_ == 0) events.push_back(enqueue_rebuild());
}

// A rebuild streams n rows: what an iteration's field updates cost when half
// the particles move (each move is two rows).
void FieldBackend::enqueue_measured_extras(std::vector<cl::Event>& events) { events.push_back(enqueue_rebuild()); }

std::vector<IterationStats> FieldBackend::iterate_without_host(Scheme scheme, unsigned colors, std::size_t count) {
  const bool schemed = scheme == Scheme::monotone || scheme == Scheme::colored;
  if (!one_launch_ || !schemed || rebuild_every_ > 0 || particle_count_ == 0 ||
      particle_count_ > kMaxOneLaunchParticles || count == 0) {
    return {};
  }
  count = std::min<std::size_t>(count, std::numeric_limits<cl_uint>::max());
  const std::size_t words = kHistoryHead + kHistoryWords * count;
  if (count > history_iterations_) {
    history_ = allocate(CL_MEM_READ_WRITE, words * sizeof(cl_ulong), "the iterations' history");
    history_iterations_ = count;
    one_launch_kernel_.setArg(kItHistory, history_);
  }
  one_launch_kernel_.setArg(kItColors, cl_uint(colors));
  one_launch_kernel_.setArg(kItMonotone, cl_uint(scheme == Scheme::monotone));
  one_launch_kernel_.setArg(kItIterations, cl_uint(count));
  const cl::NDRange work_group(kernel_.work_group_size);
  cl::Event event;
  launch(one_launch_kernel_, work_group, work_group, &event);
  std::vector<cl_ulong> history(words);
  read_blocking(history_, 0, words * sizeof(cl_ulong), history.data());

  const std::size_t run = history[0];
  const double kernel_ms = device_milliseconds(event) / double(std::max<std::size_t>(1, run));
  std::vector<IterationStats> done(run);
  for (std::size_t i = 0; i < run; ++i) {
    const cl_ulong* record = history.data() + kHistoryHead + kHistoryWords * i;
    IterationStats& stats = done[i];
    stats.moved = record[0];
    stats.energy = pair_energy_of_total(record[1]);
    stats.kernel_ms = kernel_ms;
    stats.attempts = unsigned(record[2]);
    if (scheme == Scheme::monotone) {
      stats.kept = record[3] == kKeptNone         ? "none"
                   : record[3] == kKeptSequential ? "sequential"
                                                  : "colored K=" + std::to_string(record[3]);
    }
  }
  return done;
}

double FieldBackend::total_energy() {
  std::vector<std::int64_t> energies(particle_count_);
  launch(particle_energies_, cl::NDRange(particle_count_));
  read_blocking(energies_, 0, energies.size() * sizeof(cl_long), energies.data());
  return pair_energy(energies);
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
    spec.program_files = {"field_weights.cl", "field_accumulate.cl", "field_update.cl", "apply_moves.cl",
                          "field_iterations.cl"};
    spec.takes_weight_format = true;
    // On a CPU (PoCL) wg 8 - 32 were best or near best in three sweeps at
    // sphere/1024, larger groups leave the cores idle (V / 8 work-items).
    // On a GPU the one-launch iterations run as one work-group, which wants
    // to be large: on the H100 at sphere/1024, 0.80 ms an iteration at wg 32,
    // 0.25 ms at 256; the per-colour kernels are within 30% from 1 to 256
    // there (docs/PERFORMANCE.md).
    spec.default_sizes = [](UpdateKernel& kernel, const std::string& device_type) {
      kernel.work_group_size = device_type == "GPU" ? 256 : 32;
    };
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
