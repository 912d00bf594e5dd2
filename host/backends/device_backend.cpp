#include "backends/device_backend.hpp"

#include <algorithm>

#include "geodesics/memory_guard.hpp"
#include "opencl/program_cache.hpp"

namespace meshparticles {

void check_device_limits(const DeviceDescription& device, const UpdateKernel& kernel) {
  if (kernel.work_group_size > device.max_work_group_size) {
    throw LimitExceeded("--wg " + std::to_string(kernel.work_group_size) + " exceeds the maximum work-group size " +
                        std::to_string(device.max_work_group_size) + " of " + device.name);
  }
  if (kernel.local_memory_bytes() > device.local_memory_bytes) {
    throw LimitExceeded("the " + kernel.name() + " kernel with " + kernel.sizes_text() + " needs " +
                        std::to_string(kernel.local_memory_bytes()) + " bytes of local memory; " + device.name +
                        " has " + std::to_string(device.local_memory_bytes));
  }
}

void check_device_memory(const DeviceDescription& device, const UpdateKernel& kernel, std::size_t vertex_count,
                         std::size_t edge_count, std::size_t particle_count, bool dense_table) {
  if (!dense_table) return;
  const std::string backend = "the " + kernel.name() + " backend's ";
  check_table_fits(vertex_count, sizeof(float), device.max_allocation_bytes, "table on the device",
                   "the largest buffer " + device.name + " allows");
  // Everything but the table: one-rings, claims and F (8 bytes) per vertex,
  // positions, choices, move counts and lists per particle.
  const std::uint64_t linear_bytes = 4 * (std::uint64_t(vertex_count) + 1) + 8 * std::uint64_t(edge_count) +
                                     12 * std::uint64_t(vertex_count) + 20 * std::uint64_t(particle_count);
  const std::uint64_t global = device.global_memory_bytes;
  const std::uint64_t for_table = global > linear_bytes ? global - linear_bytes : 0;
  check_table_fits(vertex_count, kernel.spec().table_bytes_per_entry(kernel), for_table, backend + "tables",
                   "the memory of " + device.name + " (after its other buffers)");
}

double device_milliseconds(const cl::Event& event) {
  return double(event.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                event.getProfilingInfo<CL_PROFILING_COMMAND_START>()) * 1e-6;
}

namespace {

cl_uint particles_of_color(cl_uint particle_count, cl_uint color, cl_uint colors) {
  return color < particle_count ? (particle_count - color + colors - 1) / colors : 0;
}

double total_milliseconds(const std::vector<cl::Event>& events) {
  double milliseconds = 0;
  for (const auto& event : events) milliseconds += device_milliseconds(event);
  return milliseconds;
}

}  // namespace

DeviceBackend::DeviceBackend(const DeviceDescription& device, const SurfaceMesh& mesh, const UpdateKernel& kernel,
                             bool dense_table)
    : device_(device), kernel_(kernel), vertex_count_(cl_uint(mesh.vertex_count())) {
  check_device_limits(device, kernel);
  check_device_memory(device, kernel, mesh.vertex_count(), mesh.edge_count(), 0, dense_table);
  context_ = device_context(device.device);
  queue_ = cl::CommandQueue(context_, device.device, CL_QUEUE_PROFILING_ENABLE);
  auto read_only = [&](const std::vector<VertexId>& values, const std::string& what) {
    return allocate(CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, values.size() * sizeof(VertexId), what, values.data());
  };
  ring_offsets_ = read_only(mesh.ring_offsets(), "the one-ring offsets");
  ring_neighbors_ = read_only(mesh.ring_neighbors().empty() ? std::vector<VertexId>{0} : mesh.ring_neighbors(),
                              "the one-rings");
  claims_ = allocate(CL_MEM_READ_WRITE, mesh.vertex_count() * sizeof(cl_uint), "the vertex claims");
  reset_claims();
}

cl::Program DeviceBackend::program(const DeviceDescription& device, Potential potential) {
  return program(device, potential, kernel_.spec().program_files);
}

cl::Program DeviceBackend::program(const DeviceDescription& device, Potential potential,
                                   const std::vector<std::string>& files) {
  const cl::Program built = cached_program(device.device, files, kernel_.defines(potential));
  apply_moves_ = cl::Kernel(built, "apply_moves");
  return built;
}

void DeviceBackend::check_kernel_limits(const cl::Kernel& kernel, const DeviceDescription& device) const {
  const std::string function = kernel.getInfo<CL_KERNEL_FUNCTION_NAME>();
  const auto work_group_limit = kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device.device);
  if (kernel_.work_group_size > work_group_limit) {
    throw LimitExceeded("--wg " + std::to_string(kernel_.work_group_size) + " exceeds the " + function +
                        " kernel's work-group limit " + std::to_string(work_group_limit) +
                        " on this device (CL_KERNEL_WORK_GROUP_SIZE)");
  }
  const auto local_bytes = kernel.getWorkGroupInfo<CL_KERNEL_LOCAL_MEM_SIZE>(device.device);
  if (local_bytes > device.local_memory_bytes) {
    throw LimitExceeded("the " + function + " kernel with " + kernel_.sizes_text() + " uses " +
                        std::to_string(local_bytes) + " bytes of local memory once compiled; " + device.name +
                        " has " + std::to_string(device.local_memory_bytes) + " (CL_KERNEL_LOCAL_MEM_SIZE)");
  }
}

cl::Buffer DeviceBackend::allocate(cl_mem_flags flags, std::size_t bytes, const std::string& what,
                                   const void* initial) {
  try {
    return cl::Buffer(context_, flags, std::max<std::size_t>(bytes, 1), const_cast<void*>(initial));
  } catch (const cl::Error& error) {
    throw UserError("cannot allocate " + what + " (" + gibibytes(double(bytes)) + ") on " + device_.name +
                    ", which has " + gibibytes(double(device_.global_memory_bytes)) + " in all and " +
                    gibibytes(double(device_.max_allocation_bytes)) + " in its largest buffer: " +
                    opencl_error_text(error.err()));
  }
}

cl::Event DeviceBackend::launch_update(cl::Kernel& update, cl_uint color_arg, cl_uint color, cl_uint colors,
                                       cl_uint particles, cl_uint rank_stacks) {
  update.setArg(color_arg, color);
  update.setArg(color_arg + 1, colors);
  update.setArg(color_arg + 2, rank_stacks);
  const std::size_t work_group = kernel_.work_group_size;
  cl::Event event;
  launch(update, cl::NDRange(kernel_.work_groups_for(particles) * work_group), cl::NDRange(work_group), &event);
  return event;
}

void DeviceBackend::launch(const cl::Kernel& kernel, const cl::NDRange& global, const cl::NDRange& local,
                           cl::Event* event) {
  queue_.enqueueNDRangeKernel(kernel, cl::NullRange, global, local, nullptr, event);
  ++traffic_.launches;
}

void DeviceBackend::read_blocking(const cl::Buffer& buffer, std::size_t offset, std::size_t bytes, void* into) {
  queue_.enqueueReadBuffer(buffer, CL_TRUE, offset, bytes, into);
  ++traffic_.host_waits;
}

void DeviceBackend::write_blocking(const cl::Buffer& buffer, std::size_t offset, std::size_t bytes,
                                   const void* from) {
  queue_.enqueueWriteBuffer(buffer, CL_TRUE, offset, bytes, from);
  ++traffic_.host_waits;
}

void DeviceBackend::wait_for_device() {
  queue_.finish();
  ++traffic_.host_waits;
}

void DeviceBackend::reset_claims() {
  queue_.enqueueFillBuffer(claims_, CL_UINT_MAX, 0, vertex_count_ * sizeof(cl_uint));
}

void DeviceBackend::set_positions(std::span<const VertexId> positions) {
  const bool resized = positions.size() != particle_count_;
  if (resized) {
    particle_count_ = cl_uint(positions.size());
    const std::size_t slots = std::max<std::size_t>(1, positions.size());
    positions_ = allocate(CL_MEM_READ_WRITE, slots * sizeof(cl_uint), "the positions");
    chosen_ = allocate(CL_MEM_READ_WRITE, slots * sizeof(cl_uint), "the choices");
    move_counts_ = allocate(CL_MEM_READ_WRITE, slots * sizeof(cl_uint), "the move counts");  // at most n colours move
    // Colour k's list starts at k * ceil(n / K) (apply_moves.cl): the last
    // colour's list may end past n, never past 2n.
    moves_ = allocate(CL_MEM_READ_WRITE, 2 * slots * sizeof(cl_uint2), "the move lists");
    apply_moves_.setArg(0, positions_);
    apply_moves_.setArg(1, chosen_);
    apply_moves_.setArg(2, particle_count_);
    apply_moves_.setArg(5, claims_);
    apply_moves_.setArg(6, move_counts_);
    apply_moves_.setArg(7, moves_);
  }
  write_blocking(positions_, 0, positions.size() * sizeof(cl_uint), positions.data());
  positions_changed(resized);
}

std::vector<VertexId> DeviceBackend::last_choices() {
  std::vector<VertexId> choices(particle_count_);
  read_blocking(chosen_, 0, choices.size() * sizeof(cl_uint), choices.data());
  return choices;
}

std::vector<VertexId> DeviceBackend::positions() {
  std::vector<VertexId> positions(particle_count_);
  read_blocking(positions_, 0, positions.size() * sizeof(cl_uint), positions.data());
  return positions;
}

cl_uint DeviceBackend::group_count(Scheme scheme, unsigned colors) const {
  return scheme == Scheme::sequential ? std::max<cl_uint>(1, particle_count_) : sub_steps(scheme, colors);
}

IterationStats DeviceBackend::iterate(Scheme scheme, unsigned colors) {
  const cl_uint groups = group_count(scheme, colors);
  const cl_uint rank_stacks = scheme == Scheme::sequential ? 0 : 1;
  const cl_uint counted = std::min(groups, particle_count_);  // colours that hold a particle
  if (counted > 0) queue_.enqueueFillBuffer(move_counts_, cl_uint{0}, 0, counted * sizeof(cl_uint));
  std::vector<cl::Event> kernel_events;
  for (cl_uint color = 0; color < counted; ++color) {
    const cl_uint particles = particles_of_color(particle_count_, color, groups);
    kernel_events.push_back(enqueue_update(color, groups, particles, rank_stacks));
    apply_moves_.setArg(3, color);
    apply_moves_.setArg(4, groups);
    launch(apply_moves_, cl::NDRange(particles));
    after_commit(color, groups, kernel_events);
  }
  after_iteration(kernel_events);
  std::vector<cl_uint> moved(counted);
  if (counted > 0) queue_.enqueueReadBuffer(move_counts_, CL_FALSE, 0, counted * sizeof(cl_uint), moved.data());
  IterationStats stats;
  stats.energy = total_energy();  // blocks, so `moved` has arrived too
  for (const cl_uint count : moved) stats.moved += count;
  stats.kernel_ms = total_milliseconds(kernel_events);
  return stats;
}

std::vector<VertexId> DeviceBackend::synchronous_choices() {
  enqueue_update(0, 1, particle_count_, 1);
  const std::vector<VertexId> choices = last_choices();
  reset_claims();  // no apply_moves followed to put them back
  return choices;
}

double DeviceBackend::time_update_kernels(Scheme scheme, unsigned colors) {
  const cl_uint groups = group_count(scheme, colors);
  std::vector<cl::Event> events;
  for (cl_uint color = 0; color < std::min(groups, particle_count_); ++color) {
    events.push_back(enqueue_update(color, groups, particles_of_color(particle_count_, color, groups),
                                    scheme == Scheme::sequential ? 0 : 1));
  }
  enqueue_measured_extras(events);
  reset_claims();
  wait_for_device();
  return total_milliseconds(events);
}

std::unique_ptr<DeviceBackend> make_device_backend(const DeviceDescription& device, const UpdateKernel& kernel,
                                                   const BackendInputs& inputs) {
  return kernel.spec().make(device, kernel, inputs);
}

}  // namespace meshparticles
