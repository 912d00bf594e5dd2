#include "particles/device_surface_voronoi.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "common/compressed_rows.hpp"
#include "common/elapsed.hpp"
#include "common/user_error.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "geodesics/triangle_stencils.hpp"
#include "opencl/program_cache.hpp"
#include "opencl/read_only_buffer.hpp"

namespace meshparticles {

namespace {

// One candidate of a target vertex from corners x and y: pull_update in
// kernels/surface_voronoi.cl, the same layout.
struct PullUpdate {
  VertexId x, y;
  PlanarFrame frame;
};
static_assert(sizeof(PullUpdate) == 20, "kernels/surface_voronoi.cl reads pull_update with this layout");

// A vertex's state in the rounds: vertex_state in kernels/surface_voronoi.cl.
struct VertexState {
  float distance;
  std::uint32_t owner;
  std::uint32_t stamp;  // round + 2 where it changed in that round; 1: a seed
  std::uint32_t unused;
};
static_assert(sizeof(VertexState) == 16, "kernels/surface_voronoi.cl reads vertex_state with this layout");

// The stencils of fast marching and the fast iterative method
// (build_triangle_stencils: listed by the vertex that triggers them) listed
// by the vertex they update, and for each vertex the vertices whose
// candidates read it.
struct PullStencils {
  std::vector<std::uint32_t> offsets;
  std::vector<PullUpdate> updates;
  std::vector<std::uint32_t> dependent_offsets;
  std::vector<VertexId> dependents;
};

PullStencils pull_stencils(const SurfaceMesh& mesh) {
  const TriangleStencils stencils = build_triangle_stencils(mesh);
  const std::size_t vertices = mesh.vertex_count();
  std::vector<std::pair<VertexId, PullUpdate>> records;  // (target, update)
  records.reserve(2 * stencils.triangles.size() + stencils.virtual_updates.size());
  // Each update is listed twice, once under each corner it reads (C from
  // (X, Y) under X, and from (Y, X) under Y: the same source placed in two
  // frames). Pulled, the two would be computed together: the one under the
  // smaller corner is kept.
  for (VertexId x = 0; x < vertices; ++x) {
    for (std::uint32_t k = stencils.triangle_offsets[x]; k < stencils.triangle_offsets[x + 1]; ++k) {
      const TriangleAtVertex& t = stencils.triangles[k];
      if (x < t.a) records.push_back({t.b, {x, t.a, t.b_from_a}});
      if (x < t.b) records.push_back({t.a, {x, t.b, t.a_from_b}});
    }
    for (std::uint32_t k = stencils.virtual_offsets[x]; k < stencils.virtual_offsets[x + 1]; ++k) {
      const VirtualUpdate& u = stencils.virtual_updates[k];
      if (x < u.other) records.push_back({u.target, {x, u.other, u.frame}});
    }
  }
  // By target, each target's in the order listed (a counting sort: man at
  // 1,024, 39k vertices, 6 ms, where a comparison sort took 21 of the
  // set-up's 67).
  PullStencils pull;
  to_compressed_rows(records, vertices, pull.offsets, pull.updates);
  // A triangle's corners are each other's one-ring neighbours; a virtual
  // update's corners may lie farther from its target: those are added.
  std::vector<std::pair<VertexId, VertexId>> far;  // (read vertex, target)
  for (VertexId target = 0; target < vertices; ++target) {
    const auto ring = mesh.one_ring(target);
    for (std::uint32_t k = pull.offsets[target]; k < pull.offsets[target + 1]; ++k) {
      for (const VertexId read : {pull.updates[k].x, pull.updates[k].y}) {
        if (std::find(ring.begin(), ring.end(), read) == ring.end()) far.push_back({read, target});
      }
    }
  }
  std::sort(far.begin(), far.end());
  far.erase(std::unique(far.begin(), far.end()), far.end());
  pull.dependent_offsets.assign(vertices + 1, 0);
  std::size_t next_far = 0;
  for (VertexId v = 0; v < vertices; ++v) {
    for (const VertexId w : mesh.one_ring(v)) pull.dependents.push_back(w);
    for (; next_far < far.size() && far[next_far].first == v; ++next_far) {
      pull.dependents.push_back(far[next_far].second);
    }
    pull.dependent_offsets[v + 1] = std::uint32_t(pull.dependents.size());
  }
  return pull;
}

// Throws UserError when the diagram's buffers would not fit `device`.
void check_voronoi_memory(const DeviceDescription& device, std::uint64_t vertices, std::uint64_t ring,
                          std::uint64_t pull_entries, std::uint64_t dependent_entries) {
  const std::uint64_t pulls = pull_entries * sizeof(PullUpdate);
  const std::uint64_t buffers[] = {
      (vertices + 1) * sizeof(cl_uint) * 3,                    // the three offset arrays
      ring * (sizeof(cl_uint) + sizeof(cl_float)),             // one-rings, edge lengths
      pulls,                                                   // the largest, about 140 B a vertex
      dependent_entries * sizeof(cl_uint),
      vertices * (2 * sizeof(VertexState) + 3)};               // the states, dirty flags
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
  const PullStencils pull = pull_stencils(mesh);
  check_voronoi_memory(device, mesh.vertex_count(), mesh.ring_neighbors().size(), pull.updates.size(),
                       pull.dependents.size());
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
  edge_lengths_ = read_only_buffer(context_, ring_edge_lengths(mesh));
  pull_offsets_ = read_only_buffer(context_, pull.offsets);
  pulls_ = read_only_buffer(context_, pull.updates);
  dependent_offsets_ = read_only_buffer(context_, pull.dependent_offsets);
  dependents_ = read_only_buffer(context_, pull.dependents);
  dependent_offsets_host_ = pull.dependent_offsets;
  dependents_host_ = pull.dependents;
  dirty_start_.resize(mesh.vertex_count());
  for (cl::Buffer& buffer : states_) buffer = cl::Buffer(context_, CL_MEM_READ_WRITE, vertices * sizeof(VertexState));
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
  // The rounds start from the corners just seeded and from every vertex
  // that kept its point and is read by an emptied one (the rims, and for
  // virtual updates a little beyond): as if each had just changed.
  std::vector<VertexId> changed = reseeded.corners;
  if (!reseeded.emptied.empty()) {
    std::vector<char> emptied(mesh_.vertex_count(), 0);
    for (const VertexId v : reseeded.emptied) emptied[v] = 1;
    for (VertexId w = 0; w < mesh_.vertex_count(); ++w) {
      if (cells.owner[w] == SurfaceVoronoi::kNoPoint) continue;
      for (std::uint32_t k = dependent_offsets_host_[w]; k < dependent_offsets_host_[w + 1]; ++k) {
        if (!emptied[dependents_host_[k]]) continue;
        changed.push_back(w);
        break;
      }
    }
  }
  if (!changed.empty()) converge(changed, cells);
  ++statistics_.diagrams;
  statistics_.seconds += seconds_since(started);
}

void DeviceSurfaceVoronoi::converge(std::span<const VertexId> changed, SurfaceVoronoi& voronoi) {
  const std::size_t vertices = mesh_.vertex_count();
  // Both buffers start as `voronoi`; round 0 computes the vertices that
  // read a changed one, from it (stamped 1: changed before round 0).
  std::vector<VertexState> states(vertices);
  for (std::size_t v = 0; v < vertices; ++v) states[v] = {voronoi.distance[v], voronoi.owner[v], 0, 0};
  std::fill(dirty_start_.begin(), dirty_start_.end(), cl_uchar(0));
  for (const VertexId c : changed) {
    states[c].stamp = 1;
    for (std::uint32_t k = dependent_offsets_host_[c]; k < dependent_offsets_host_[c + 1]; ++k) {
      dirty_start_[dependents_host_[k]] = 1;
    }
  }
  for (const cl::Buffer& buffer : states_) {
    queue_.enqueueWriteBuffer(buffer, CL_FALSE, 0, vertices * sizeof(VertexState), states.data());
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
  queue_.enqueueReadBuffer(states_[round % 2], CL_TRUE, 0, vertices * sizeof(VertexState), states.data());
  for (std::size_t v = 0; v < vertices; ++v) {
    voronoi.distance[v] = states[v].distance;
    voronoi.owner[v] = states[v].owner;
  }
}

}  // namespace meshparticles
