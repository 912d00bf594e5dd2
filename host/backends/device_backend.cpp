#include "backends/device_backend.hpp"

#include "geodesics/memory_guard.hpp"

namespace meshparticles {

void check_device_limits(const DeviceDescription& device, const UpdateKernel& kernel) {
  if (kernel.work_group_size > device.max_work_group_size) {
    throw LimitExceeded("--wg " + std::to_string(kernel.work_group_size) + " exceeds the maximum work-group size " +
                    std::to_string(device.max_work_group_size) + " of " + device.name);
  }
  if (kernel.local_memory_bytes() > device.local_memory_bytes) {
    throw LimitExceeded("the " + kernel_kind_name(kernel.kind) + " kernel with --wg " +
                    std::to_string(kernel.work_group_size) +
                    (kernel.kind == KernelKind::tiled ? " --tile " + std::to_string(kernel.tile_size) : "") +
                    " needs " + std::to_string(kernel.local_memory_bytes()) + " bytes of local memory; " +
                    device.name + " has " + std::to_string(device.local_memory_bytes));
  }
}

namespace {

void check_kernel_limits(const cl::Kernel& update, const cl::Device& device, const UpdateKernel& kernel) {
  const auto kernel_limit = update.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device);
  if (kernel.work_group_size > kernel_limit) {
    throw LimitExceeded("--wg " + std::to_string(kernel.work_group_size) + " exceeds the " +
                    kernel_kind_name(kernel.kind) + " kernel's work-group limit " + std::to_string(kernel_limit) +
                    " on this device (CL_KERNEL_WORK_GROUP_SIZE)");
  }
}

cl_uint particles_of_color(cl_uint particle_count, cl_uint color, cl_uint colors) {
  return color < particle_count ? (particle_count - color + colors - 1) / colors : 0;
}

void require_device_scheme(Scheme scheme) {
  if (scheme == Scheme::sequential) throw UserError("the " + scheme_name(scheme) + " scheme runs only on --backend serial");
}

double event_milliseconds(const cl::Event& event) {
  return double(event.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                event.getProfilingInfo<CL_PROFILING_COMMAND_START>()) * 1e-6;
}

}  // namespace

DeviceBackend::DeviceBackend(const DeviceDescription& device, const SurfaceMesh& mesh, const DistanceTable& distances,
                             const EnergyParams& energy, const UpdateKernel& kernel)
    : device_name_(device.name), kernel_(kernel), vertex_count_(cl_uint(mesh.vertex_count())) {
  check_device_limits(device, kernel);
  check_distance_table_fits(mesh.vertex_count(), device.max_allocation_bytes,
                            "the largest buffer " + device.name + " allows");
  context_ = cl::Context(device.device);
  queue_ = cl::CommandQueue(context_, device.device, CL_QUEUE_PROFILING_ENABLE);
  const cl::Program program = build_program(context_, device.device,
                                            {kernel.file(), "apply_moves.cl", "particle_energies.cl"},
                                            kernel.defines(energy.potential));
  update_ = cl::Kernel(program, kernel.function().c_str());
  claim_targets_ = cl::Kernel(program, "claim_targets");
  apply_moves_ = cl::Kernel(program, "apply_moves");
  particle_energies_ = cl::Kernel(program, "particle_energies");
  check_kernel_limits(update_, device.device, kernel);

  auto read_only = [&](const auto& values) {
    using Value = typename std::decay_t<decltype(values)>::value_type;
    return cl::Buffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, values.size() * sizeof(Value),
                      const_cast<Value*>(values.data()));
  };
  distances_ = read_only(distances.values());
  ring_offsets_ = read_only(mesh.ring_offsets());
  ring_neighbors_ = read_only(mesh.ring_neighbors().empty() ? std::vector<VertexId>{0} : mesh.ring_neighbors());
  moved_count_ = cl::Buffer(context_, CL_MEM_READ_WRITE, sizeof(cl_uint));
  claims_ = cl::Buffer(context_, CL_MEM_READ_WRITE, mesh.vertex_count() * sizeof(cl_uint));

  const float inv_two_sigma_sq = float(energy.inv_two_sigma_sq());
  update_.setArg(0, distances_);
  update_.setArg(1, vertex_count_);
  update_.setArg(2, ring_offsets_);
  update_.setArg(3, ring_neighbors_);
  update_.setArg(8, inv_two_sigma_sq);
  particle_energies_.setArg(0, distances_);
  particle_energies_.setArg(1, vertex_count_);
  particle_energies_.setArg(4, inv_two_sigma_sq);
}

void DeviceBackend::set_positions(std::span<const VertexId> positions) {
  if (positions.size() != particle_count_) {
    particle_count_ = cl_uint(positions.size());
    positions_ = cl::Buffer(context_, CL_MEM_READ_WRITE, positions.size() * sizeof(cl_uint));
    chosen_ = cl::Buffer(context_, CL_MEM_READ_WRITE, positions.size() * sizeof(cl_uint));
    energies_ = cl::Buffer(context_, CL_MEM_READ_WRITE, positions.size() * sizeof(cl_float));
    update_.setArg(4, positions_);
    update_.setArg(5, particle_count_);
    update_.setArg(9, chosen_);
    for (cl::Kernel* commit : {&claim_targets_, &apply_moves_}) {
      commit->setArg(0, positions_);
      commit->setArg(1, chosen_);
      commit->setArg(2, particle_count_);
      commit->setArg(5, claims_);
    }
    apply_moves_.setArg(6, moved_count_);
    particle_energies_.setArg(2, positions_);
    particle_energies_.setArg(3, particle_count_);
    particle_energies_.setArg(5, energies_);
  }
  queue_.enqueueWriteBuffer(positions_, CL_TRUE, 0, positions.size() * sizeof(cl_uint), positions.data());
}

std::vector<VertexId> DeviceBackend::last_choices() {
  std::vector<VertexId> choices(particle_count_);
  queue_.enqueueReadBuffer(chosen_, CL_TRUE, 0, choices.size() * sizeof(cl_uint), choices.data());
  return choices;
}

std::vector<VertexId> DeviceBackend::positions() {
  std::vector<VertexId> positions(particle_count_);
  queue_.enqueueReadBuffer(positions_, CL_TRUE, 0, positions.size() * sizeof(cl_uint), positions.data());
  return positions;
}

IterationStats DeviceBackend::iterate(Scheme scheme, unsigned colors) {
  require_device_scheme(scheme);
  const cl_uint groups = sub_steps(scheme, colors);
  queue_.enqueueFillBuffer(moved_count_, cl_uint{0}, 0, sizeof(cl_uint));
  std::vector<cl::Event> update_events;
  for (cl_uint color = 0; color < groups; ++color) {
    const cl_uint particles = particles_of_color(particle_count_, color, groups);
    if (particles == 0) continue;
    update_events.push_back(enqueue_update(color, groups, particles));
    queue_.enqueueFillBuffer(claims_, CL_UINT_MAX, 0, vertex_count_ * sizeof(cl_uint));
    for (cl::Kernel* commit : {&claim_targets_, &apply_moves_}) {
      commit->setArg(3, color);
      commit->setArg(4, groups);
    }
    queue_.enqueueNDRangeKernel(claim_targets_, cl::NullRange, cl::NDRange(particles));
    queue_.enqueueNDRangeKernel(apply_moves_, cl::NullRange, cl::NDRange(particles));
  }
  IterationStats stats;
  cl_uint moved = 0;
  queue_.enqueueReadBuffer(moved_count_, CL_FALSE, 0, sizeof moved, &moved);
  stats.energy = total_energy();  // blocks, so `moved` has arrived too
  stats.moved = moved;
  double kernel_ms = 0;
  for (const auto& event : update_events) kernel_ms += event_milliseconds(event);
  stats.kernel_ms = kernel_ms;
  return stats;
}

cl::Event DeviceBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles) {
  update_.setArg(6, color);
  update_.setArg(7, colors);
  const std::size_t work_group = kernel_.work_group_size;
  cl::Event event;
  queue_.enqueueNDRangeKernel(update_, cl::NullRange, cl::NDRange(kernel_.work_groups_for(particles) * work_group),
                              cl::NDRange(work_group), nullptr, &event);
  return event;
}

std::vector<VertexId> DeviceBackend::synchronous_choices() {
  enqueue_update(0, 1, particle_count_);
  return last_choices();
}

double DeviceBackend::time_update_kernels(Scheme scheme, unsigned colors) {
  require_device_scheme(scheme);
  const cl_uint groups = sub_steps(scheme, colors);
  std::vector<cl::Event> events;
  for (cl_uint color = 0; color < groups; ++color) {
    const cl_uint particles = particles_of_color(particle_count_, color, groups);
    if (particles > 0) events.push_back(enqueue_update(color, groups, particles));
  }
  queue_.finish();
  double milliseconds = 0;
  for (const auto& event : events) milliseconds += event_milliseconds(event);
  return milliseconds;
}

double DeviceBackend::total_energy() {
  std::vector<float> energies(particle_count_);
  queue_.enqueueNDRangeKernel(particle_energies_, cl::NullRange, cl::NDRange(particle_count_));
  queue_.enqueueReadBuffer(energies_, CL_TRUE, 0, energies.size() * sizeof(float), energies.data());
  double sum = 0;
  for (const float e : energies) sum += e;
  return sum / 2;  // every pair was counted from both ends
}

}  // namespace meshparticles
