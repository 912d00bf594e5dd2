#include "particles/device_surface_voronoi.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "common/elapsed.hpp"
#include "common/user_error.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "opencl/program_cache.hpp"
#include "opencl/read_only_buffer.hpp"
#include "particles/surface_voronoi_rounds.hpp"

namespace meshparticles {

namespace {

// Throws UserError when the diagram's buffers would not fit `device`.
void check_voronoi_memory(const DeviceDescription& device, std::uint64_t vertices, std::uint64_t ring,
                          std::uint64_t pull_entries, std::uint64_t dependent_entries) {
  const std::uint64_t pulls = pull_entries * sizeof(pull_update);
  const std::uint64_t buffers[] = {
      (vertices + 1) * sizeof(cl_uint) * 3,                    // the three offset arrays
      ring * (sizeof(cl_uint) + sizeof(cl_float)),             // one-rings, edge lengths
      pulls,                                                   // the largest, about 140 B a vertex
      dependent_entries * sizeof(cl_uint),
      vertices * (2 * sizeof(vertex_state) + 3)};               // the states, dirty flags
  std::uint64_t total = 0;
  for (const std::uint64_t bytes : buffers) total += bytes;
  const auto mib = [](std::uint64_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; };
  if (total > device.global_memory_bytes || pulls > device.max_allocation_bytes) {
    throw UserError("the evening's Voronoi diagram on " + device.name + " needs " + mib(total) +
                    " of device memory, " + mib(pulls) + " in one buffer; it has " + mib(device.global_memory_bytes) +
                    ", at most " + mib(device.max_allocation_bytes) + " in one buffer: run without --device");
  }
}

// Rounds queued between two looks at the flags: a diagram takes 10 to 30
// on the meshes measured, and a round after the last costs a scan of the
// flags only.
constexpr std::size_t kBatchRounds = 16;
constexpr std::size_t kWorkGroupSize = 256;

}  // namespace

void check_device_voronoi_fits(const DeviceDescription& device, std::uint64_t vertices) {
  // A closed mesh's: six neighbours a vertex, a candidate from each of its
  // six triangles, and about one virtual update a vertex.
  check_voronoi_memory(device, vertices, 6 * vertices, 7 * vertices, 7 * vertices);
}

DeviceSurfaceVoronoi::DeviceSurfaceVoronoi(const SurfaceMesh& mesh, const DeviceDescription& device)
    : mesh_(mesh), device_name_(device.name) {
  stencils_ = voronoi_stencils_of(mesh);
  check_voronoi_memory(device, mesh.vertex_count(), mesh.ring_neighbors().size(), stencils_.pulls.size(),
                       stencils_.dependents.size());
  context_ = device_context(device.device);
  queue_ = cl::CommandQueue(context_, device.device);
  const cl::Program program = cached_program(device.device, {"surface_voronoi.cl"}, {}, FloatMath::exact);
  kernel_ = cl::Kernel(program, "surface_voronoi_round");
  // Left to the runtime, PoCL takes work-groups of one item: a round costs
  // its scheduling of every vertex (6 ms a round at 48k vertices).
  work_group_size_ = std::min<std::size_t>(
      {kWorkGroupSize, device.max_work_group_size,
       kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device.device)});
  const std::size_t vertices = std::max<std::size_t>(mesh.vertex_count(), 1);
  ring_offsets_ = read_only_buffer(context_, mesh.ring_offsets());
  ring_neighbors_ = read_only_buffer(context_, mesh.ring_neighbors());
  edge_lengths_ = read_only_buffer(context_, stencils_.edge_lengths);
  pull_offsets_ = read_only_buffer(context_, stencils_.pull_offsets);
  pulls_ = read_only_buffer(context_, stencils_.pulls);
  dependent_offsets_ = read_only_buffer(context_, stencils_.dependent_offsets);
  dependents_ = read_only_buffer(context_, stencils_.dependents);
  // The host keeps what marks round 0's vertices (the dependents), not the
  // candidates, the largest part.
  stencils_.pulls = {};
  stencils_.pull_offsets = {};
  stencils_.edge_lengths = {};
  dirty_start_.resize(mesh.vertex_count());
  for (cl::Buffer& buffer : states_) buffer = cl::Buffer(context_, CL_MEM_READ_WRITE, vertices * sizeof(vertex_state));
  for (cl::Buffer& buffer : dirty_) buffer = cl::Buffer(context_, CL_MEM_READ_WRITE, vertices * sizeof(cl_uchar));
  round_changed_ = cl::Buffer(context_, CL_MEM_READ_WRITE, kBatchRounds * sizeof(cl_uint));
  kernel_.setArg(0, cl_uint(mesh.vertex_count()));
  kernel_.setArg(2, ring_offsets_);
  kernel_.setArg(3, ring_neighbors_);
  kernel_.setArg(4, edge_lengths_);
  kernel_.setArg(5, pull_offsets_);
  kernel_.setArg(6, pulls_);
  kernel_.setArg(7, dependent_offsets_);
  kernel_.setArg(8, dependents_);
  kernel_.setArg(14, round_changed_);
}

SurfaceVoronoi DeviceSurfaceVoronoi::diagram(std::span<const SurfaceLocation> points) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<VertexId> seeds;
  SurfaceVoronoi voronoi = seeded_surface_voronoi(mesh_, points, seeds);
  if (!seeds.empty() && mesh_.vertex_count() > 0) converge(seeds, voronoi);
  ++statistics_.diagrams;
  statistics_.seconds += seconds_since(started);
  return voronoi;
}

void DeviceSurfaceVoronoi::update(std::span<const SurfaceLocation> points, std::span<const char> moved,
                                  SurfaceVoronoi& cells) {
  const auto started = std::chrono::steady_clock::now();
  const MovedPointsReseeded reseeded = reseed_moved_points(mesh_, points, moved, cells);
  const std::vector<VertexId> changed = rounds_start_after_moves(stencils_, reseeded, cells);
  if (!changed.empty()) converge(changed, cells);
  ++statistics_.diagrams;
  statistics_.seconds += seconds_since(started);
}

void DeviceSurfaceVoronoi::converge(std::span<const VertexId> changed, SurfaceVoronoi& voronoi) {
  const std::size_t vertices = mesh_.vertex_count();
  // Both buffers start as `voronoi`; round 0 computes the vertices that
  // read a changed one, from it (stamped 1: changed before round 0).
  std::vector<vertex_state> states(vertices);
  for (std::size_t v = 0; v < vertices; ++v) states[v] = {voronoi.distance[v], voronoi.owner[v], 0, 0};
  std::fill(dirty_start_.begin(), dirty_start_.end(), cl_uchar(0));
  for (const VertexId c : changed) {
    states[c].stamp = 1;
    for (std::uint32_t k = stencils_.dependent_offsets[c]; k < stencils_.dependent_offsets[c + 1]; ++k) {
      dirty_start_[stencils_.dependents[k]] = 1;
    }
  }
  for (const cl::Buffer& buffer : states_) {
    queue_.enqueueWriteBuffer(buffer, CL_FALSE, 0, vertices * sizeof(vertex_state), states.data());
  }
  queue_.enqueueWriteBuffer(dirty_[0], CL_FALSE, 0, vertices, dirty_start_.data());
  queue_.enqueueFillBuffer(dirty_[1], cl_uchar(0), 0, vertices);
  // Lexicographic (distance, owner) falls at every change, so the rounds
  // end; this bound only guards against a broken device.
  const std::size_t most_rounds = 4 * vertices + 64;
  std::size_t round = 0;
  const std::size_t batch = kBatchRounds;
  std::vector<cl_uint> round_flags(kBatchRounds);
  const std::size_t global = (vertices + work_group_size_ - 1) / work_group_size_ * work_group_size_;
  for (bool converged = false; !converged;) {
    if (round > most_rounds) throw std::runtime_error("the device's Voronoi diagram did not converge");
    queue_.enqueueFillBuffer(round_changed_, cl_uint(0), 0, batch * sizeof(cl_uint));
    for (std::size_t k = 0; k < batch; ++k, ++round) {
      kernel_.setArg(1, cl_uint(round));
      kernel_.setArg(9, states_[round % 2]);
      kernel_.setArg(10, states_[(round + 1) % 2]);
      kernel_.setArg(11, dirty_[round % 3]);
      kernel_.setArg(12, dirty_[(round + 1) % 3]);
      kernel_.setArg(13, dirty_[(round + 2) % 3]);
      kernel_.setArg(15, cl_uint(k));
      queue_.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(work_group_size_));
    }
    queue_.enqueueReadBuffer(round_changed_, CL_TRUE, 0, batch * sizeof(cl_uint), round_flags.data());
    ++statistics_.batches;
    const auto rounds_changed = std::size_t(std::count(round_flags.begin(), round_flags.begin() + std::ptrdiff_t(batch), 1u));
    statistics_.rounds += rounds_changed;
    converged = rounds_changed < batch;
  }
  // The last round changed nothing: the buffers it wrote hold every vertex.
  queue_.enqueueReadBuffer(states_[round % 2], CL_TRUE, 0, vertices * sizeof(vertex_state), states.data());
  for (std::size_t v = 0; v < vertices; ++v) {
    voronoi.distance[v] = states[v].distance;
    voronoi.owner[v] = states[v].owner;
  }
}

}  // namespace meshparticles
