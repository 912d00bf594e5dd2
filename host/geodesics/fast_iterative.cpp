#include "geodesics/fast_iterative.hpp"

#include <algorithm>
#include <limits>

#include "geodesics/point_source_update.hpp"

namespace meshparticles {

double fim_margin(const SurfaceMesh& mesh, const TriangleStencils& stencils) {
  double longest = 0;
  for (const float length : ring_edge_lengths(mesh)) longest = std::max(longest, double(length));
  for (const TriangleAtVertex& t : stencils.triangles) {
    longest = std::max({longest, double(t.b_from_a.length_xy), double(t.a_from_b.length_xy)});
  }
  for (const VirtualUpdate& u : stencils.virtual_updates) longest = std::max(longest, double(u.frame.length_xy));
  return longest;
}

FastIterativeMethod::FastIterativeMethod(const SurfaceMesh& mesh)
    : GeodesicSolver(mesh.vertex_count()),
      mesh_(mesh),
      edge_lengths_(ring_edge_lengths(mesh)),
      stencils_(build_triangle_stencils(mesh)),
      margin_(fim_margin(mesh, stencils_)) {}

void FastIterativeMethod::march(std::span<const VertexId> sources, std::span<double> distances,
                                SolverScratch& scratch, double max_distance, std::span<const float> bound,
                                std::span<const std::uint32_t> origins) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // Distances up to `keep` are kept, so that those within max_distance come
  // out as an unlimited solve gives them (fim_margin).
  const double keep = max_distance + margin_;
  // heap_slot marks the vertices listed in `next` (kNotQueued otherwise).
  std::vector<std::uint32_t>& queued = scratch.heap_slot;
  std::vector<std::uint32_t>& origin = scratch.origin;
  std::vector<VertexId>& active = scratch.active;
  std::vector<VertexId>& next = scratch.next_active;
  active.clear();
  next.clear();
  for (std::uint32_t k = 0; k < sources.size(); ++k) {
    const VertexId source = sources[k];
    if (origins.empty()) {
      if (distances[source] == kInfinity) scratch.touched.push_back(source);
      distances[source] = 0.0;
    }
    origin[source] = origins.empty() ? k : origins[k];
    if (queued[source] == SolverScratch::kNotQueued) {
      queued[source] = 0;
      active.push_back(source);
    }
  }
  const bool several_sources = sources.size() > 1 || !origins.empty();
  const auto lower = [&](VertexId v, double candidate, std::uint32_t from) {
    if (!(candidate <= keep) || !(candidate < distances[v])) return;
    if (!bound.empty() && candidate >= double(bound[v])) return;
    if (distances[v] == kInfinity) scratch.touched.push_back(v);
    distances[v] = candidate;
    origin[v] = from;
    if (queued[v] == SolverScratch::kNotQueued) {
      queued[v] = 0;
      next.push_back(v);
    }
  };
  // A point-source update reads only corners measured from the same source
  // (see fast_marching.cpp); edges may always lower.
  const auto reached = [&](VertexId other, VertexId x) {
    return distances[other] < kInfinity && (!several_sources || origin[other] == origin[x]);
  };
  const auto& offsets = mesh_.ring_offsets();
  const auto& neighbors = mesh_.ring_neighbors();
  while (!active.empty()) {
    for (const VertexId x : active) {
      queued[x] = SolverScratch::kNotQueued;
      const double dx = distances[x];
      const std::uint32_t from = origin[x];
      for (std::uint32_t k = offsets[x]; k < offsets[x + 1]; ++k) lower(neighbors[k], dx + edge_lengths_[k], from);
      for (std::uint32_t k = stencils_.triangle_offsets[x]; k < stencils_.triangle_offsets[x + 1]; ++k) {
        const TriangleAtVertex& t = stencils_.triangles[k];
        if (reached(t.a, x)) lower(t.b, point_source_update(t.b_from_a, dx, distances[t.a]), from);
        if (reached(t.b, x)) lower(t.a, point_source_update(t.a_from_b, dx, distances[t.b]), from);
      }
      for (std::uint32_t k = stencils_.virtual_offsets[x]; k < stencils_.virtual_offsets[x + 1]; ++k) {
        const VirtualUpdate& u = stencils_.virtual_updates[k];
        if (reached(u.other, x)) lower(u.target, point_source_update(u.frame, dx, distances[u.other]), from);
      }
    }
    active.swap(next);
    next.clear();
  }
  for (const VertexId v : scratch.touched) scratch.accepted[v] = distances[v] <= max_distance ? 1 : 0;
}

}  // namespace meshparticles
