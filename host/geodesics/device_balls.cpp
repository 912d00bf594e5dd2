#include "geodesics/device_balls.hpp"

#include <algorithm>
#include <chrono>

#include "common/elapsed.hpp"
#include "common/parallel_for.hpp"
#include "common/user_error.hpp"
#include "opencl/program_cache.hpp"
#include "opencl/read_only_buffer.hpp"

namespace meshparticles {

namespace {

static_assert(sizeof(TriangleAtVertex) == 32 && sizeof(VirtualUpdate) == 20,
              "kernels/fim_balls.cl reads the stencils with this layout");

// Per slot: vertex id, distance bits, active flag.
constexpr std::size_t kBytesPerSlot = 9;
constexpr unsigned kLargestSlotBits = 12;  // 4,096 vertices: 36 KB, inside the 48 KB every GPU offers
constexpr unsigned kSmallestSlotBits = 8;
// Output per launch at most (each ball gets a whole table's room).
constexpr std::uint64_t kLaunchOutputBytes = std::uint64_t{256} << 20;

unsigned slot_bits_for(const DeviceDescription& device) {
  for (unsigned bits = kLargestSlotBits; bits > kSmallestSlotBits; --bits) {
    if ((std::uint64_t{1} << bits) * kBytesPerSlot + 64 <= device.local_memory_bytes) return bits;
  }
  return kSmallestSlotBits;
}

std::size_t balls_per_launch_for(const DeviceDescription& device) {
  const std::uint64_t per_ball = (std::uint64_t{1} << slot_bits_for(device)) * (sizeof(cl_uint) + sizeof(cl_float));
  const std::uint64_t allowed = std::min<std::uint64_t>(kLaunchOutputBytes, device.max_allocation_bytes / 2);
  return std::size_t(std::max<std::uint64_t>(1, allowed / per_ball));
}

// Throws UserError when the buffers of a mesh of these sizes would not fit `device`.
void check_ball_memory(const DeviceDescription& device, std::uint64_t vertices, std::uint64_t ring,
                       std::uint64_t triangles_at_vertices, std::uint64_t virtual_updates) {
  const std::uint64_t balls_per_launch = balls_per_launch_for(device);
  const std::uint64_t output = balls_per_launch * device_ball_slots(device) * sizeof(cl_uint);
  const std::uint64_t largest = triangles_at_vertices * sizeof(TriangleAtVertex);  // about 200 B a vertex
  const std::uint64_t buffers[] = {
      (vertices + 1) * sizeof(cl_uint) * 3,                    // the three offset arrays
      ring * (sizeof(cl_uint) + sizeof(cl_float)),             // one-rings, edge lengths
      largest,                                                 // the triangles at each vertex
      virtual_updates * sizeof(VirtualUpdate),
      2 * output,                                              // ball vertices and distances
      balls_per_launch * 3 * sizeof(cl_uint)};                 // sources, sizes, starts
  std::uint64_t total = 0;
  for (const std::uint64_t bytes : buffers) total += bytes;
  const auto mib = [](std::uint64_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; };
  if (total > device.global_memory_bytes || largest > device.max_allocation_bytes) {
    throw UserError("the fast iterative method's balls on " + device.name + " need " + mib(total) +
                    " of device memory, " + mib(largest) + " in one buffer; it has " +
                    mib(device.global_memory_bytes) + ", at most " + mib(device.max_allocation_bytes) +
                    " in one buffer: use --geodesic fmm");
  }
}

}  // namespace

std::size_t device_ball_slots(const DeviceDescription& device) { return std::size_t{1} << slot_bits_for(device); }

void check_device_balls_fit(const DeviceDescription& device, std::uint64_t vertices) {
  // A closed mesh's: six neighbours and six triangle corners a vertex, and
  // about one virtual update a vertex.
  check_ball_memory(device, vertices, 6 * vertices, 6 * vertices, vertices);
}

DeviceBallSolver::DeviceBallSolver(const SurfaceMesh& mesh, const FastIterativeMethod& host,
                                   const DeviceDescription& device, unsigned threads)
    : host_(host), host_scratch_(cores_or(threads)), device_(device), slot_bits_(slot_bits_for(device)) {
  work_group_size_ = std::min<std::size_t>(device.is_gpu() ? 256 : 64, device.max_work_group_size);
  balls_per_launch_ = balls_per_launch_for(device);
  const TriangleStencils& stencils = host_.stencils();
  check_ball_memory(device, mesh.vertex_count(), mesh.ring_neighbors().size(), stencils.triangles.size(),
                    stencils.virtual_updates.size());
  context_ = device_context(device.device);
  queue_ = cl::CommandQueue(context_, device.device, CL_QUEUE_PROFILING_ENABLE);
  const cl::Program program = cached_program(
      device.device, {"fim_balls.cl"},
      {{"SLOT_BITS", slot_bits_}, {"WORK_GROUP_SIZE", static_cast<long long>(work_group_size_)}});
  kernel_ = cl::Kernel(program, "fim_balls");
  ring_offsets_ = read_only_buffer(context_, mesh.ring_offsets());
  ring_neighbors_ = read_only_buffer(context_, mesh.ring_neighbors());
  edge_lengths_ = read_only_buffer(context_, host_.edge_lengths());
  triangle_offsets_ = read_only_buffer(context_, stencils.triangle_offsets);
  triangles_ = read_only_buffer(context_, stencils.triangles);
  virtual_offsets_ = read_only_buffer(context_, stencils.virtual_offsets);
  virtual_updates_ = read_only_buffer(context_, stencils.virtual_updates);
  sources_ = cl::Buffer(context_, CL_MEM_READ_ONLY, balls_per_launch_ * sizeof(cl_uint));
  ball_vertices_ = cl::Buffer(context_, CL_MEM_WRITE_ONLY, balls_per_launch_ * slots() * sizeof(cl_uint));
  ball_distances_ = cl::Buffer(context_, CL_MEM_WRITE_ONLY, balls_per_launch_ * slots() * sizeof(cl_float));
  ball_sizes_ = cl::Buffer(context_, CL_MEM_WRITE_ONLY, balls_per_launch_ * sizeof(cl_uint));
  ball_starts_ = cl::Buffer(context_, CL_MEM_WRITE_ONLY, balls_per_launch_ * sizeof(cl_uint));
  entries_used_ = cl::Buffer(context_, CL_MEM_READ_WRITE, sizeof(cl_uint));
  kernel_.setArg(4, ring_offsets_);
  kernel_.setArg(5, ring_neighbors_);
  kernel_.setArg(6, edge_lengths_);
  kernel_.setArg(7, triangle_offsets_);
  kernel_.setArg(8, triangles_);
  kernel_.setArg(9, virtual_offsets_);
  kernel_.setArg(10, virtual_updates_);
  kernel_.setArg(11, ball_vertices_);
  kernel_.setArg(12, ball_distances_);
  kernel_.setArg(13, ball_sizes_);
  kernel_.setArg(14, ball_starts_);
  kernel_.setArg(15, entries_used_);
  kernel_.setArg(0, sources_);
}

// One launch's balls as read back: sizes, where each starts in the packed entries.
struct DeviceBallSolver::Launch {
  std::size_t first = 0, count = 0;
  std::vector<cl_uint> sizes, starts, vertices;
  std::vector<cl_float> distances;
  cl::Event done;
};

void DeviceBallSolver::enqueue(std::span<const VertexId> sources, Launch& launch) {
  static const cl_uint kNone = 0;  // static: the write below may happen after this returns
  queue_.enqueueWriteBuffer(entries_used_, CL_FALSE, 0, sizeof kNone, &kNone);
  queue_.enqueueWriteBuffer(sources_, CL_FALSE, 0, launch.count * sizeof(cl_uint), sources.data() + launch.first);
  kernel_.setArg(1, cl_uint(launch.count));
  queue_.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(launch.count * work_group_size_),
                              cl::NDRange(work_group_size_), nullptr, &launch.done);
  queue_.flush();
  ++statistics_.launches;
}

void DeviceBallSolver::read_back(Launch& launch) {
  cl_uint used = 0;
  launch.sizes.resize(launch.count);
  launch.starts.resize(launch.count);
  queue_.enqueueReadBuffer(ball_sizes_, CL_FALSE, 0, launch.count * sizeof(cl_uint), launch.sizes.data());
  queue_.enqueueReadBuffer(ball_starts_, CL_FALSE, 0, launch.count * sizeof(cl_uint), launch.starts.data());
  queue_.enqueueReadBuffer(entries_used_, CL_TRUE, 0, sizeof used, &used);
  launch.vertices.resize(used);
  launch.distances.resize(used);
  if (used > 0) {
    queue_.enqueueReadBuffer(ball_vertices_, CL_FALSE, 0, used * sizeof(cl_uint), launch.vertices.data());
    queue_.enqueueReadBuffer(ball_distances_, CL_TRUE, 0, used * sizeof(cl_float), launch.distances.data());
  }
  statistics_.kernel_seconds += double(launch.done.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                       launch.done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) *
                                1e-9;
}

std::vector<Ball> DeviceBallSolver::solve_balls(std::span<const VertexId> sources, double radius,
                                               const std::function<void(std::size_t)>& solved) {
  constexpr cl_uint kUnsolved = 0xFFFFFFFFu;  // BALL_UNSOLVED in the kernel
  const auto started = std::chrono::steady_clock::now();
  std::vector<Ball> balls(sources.size());
  kernel_.setArg(2, cl_float(radius));
  kernel_.setArg(3, cl_float(radius + host_.margin()));
  std::size_t done = 0;
  const auto tell = [&] {
    if (solved) solved(done);
  };
  // The balls too big for the device, on every thread the solver was given,
  // a few at a time so that `solved` hears of them: on a fine mesh every
  // ball of a wide radius may be one (cheese's 93k vertices at 7 spacings:
  // 1,024 balls of 20k to 40k vertices, 59 s on two cores).
  const auto solve_on_host = [&](const std::vector<std::size_t>& indices) {
    const std::size_t piece = 4 * host_scratch_.size();
    for (std::size_t first = 0; first < indices.size(); first += piece) {
      const std::size_t count = std::min(piece, indices.size() - first);
      for_each_with_slot(count, unsigned(host_scratch_.size()), [&](std::size_t k, unsigned slot) {
        const std::size_t index = indices[first + k];
        balls[index] = host_.solve_ball(sources[index], radius, host_scratch_[slot]);
      });
      statistics_.solved_on_host += count;
      done += count;
      tell();
    }
  };
  // The host unpacks one launch (and solves its balls too big for the
  // device) while the device runs the next.
  Launch launches[2];
  const auto unpack = [&](const Launch& launch) {
    std::vector<std::size_t> too_big;
    for (std::size_t k = 0; k < launch.count; ++k) {
      Ball& ball = balls[launch.first + k];
      if (launch.sizes[k] == kUnsolved) {
        too_big.push_back(launch.first + k);
        continue;
      }
      const auto begin = std::ptrdiff_t(launch.starts[k]), end = begin + std::ptrdiff_t(launch.sizes[k]);
      ball.vertices.assign(launch.vertices.begin() + begin, launch.vertices.begin() + end);
      ball.distances.assign(launch.distances.begin() + begin, launch.distances.begin() + end);
    }
    done += launch.count - too_big.size();
    tell();
    solve_on_host(too_big);
  };
  std::size_t index = 0;
  for (std::size_t first = 0; first < sources.size(); first += balls_per_launch_, ++index) {
    Launch& launch = launches[index % 2];
    launch.first = first;
    launch.count = std::min(balls_per_launch_, sources.size() - first);
    if (index == 0) enqueue(sources, launch);
    read_back(launch);
    Launch& next = launches[(index + 1) % 2];
    next.first = first + launch.count;
    next.count = std::min(balls_per_launch_, sources.size() - next.first);
    if (next.count > 0) enqueue(sources, next);
    unpack(launch);
  }
  statistics_.balls += sources.size();
  statistics_.seconds += seconds_since(started);
  return balls;
}

}  // namespace meshparticles
