#include "geodesics/fast_iterative.hpp"

#include <algorithm>
#include <limits>

#include "geodesics/point_source_update.hpp"
#include "geodesics/shortest_first_queue.hpp"

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

FastIterativeMethod::FastIterativeMethod(const SurfaceMesh& mesh, unsigned threads)
    : GeodesicSolver(mesh.vertex_count()),
      mesh_(mesh),
      edge_lengths_(ring_edge_lengths(mesh)),
      stencils_(build_triangle_stencils(mesh, threads)),
      margin_(fim_margin(mesh, stencils_)) {}

namespace {

// A vertex is lowered only by more than this share of its distance. Updates
// that are not monotone can lower two vertices in turn by ever smaller steps:
// in double precision such a pair went on for 10^7 steps (cheese's balls at
// quality's cutoff: 27 s for one ball of 28k vertices, 0.15 s with this
// floor). About a float's resolution, which the device's rounds stop at.
constexpr double kLeastDrop = 1e-7;

}  // namespace

void FastIterativeMethod::march(std::span<const VertexId> sources, std::span<double> distances,
                                SolverScratch& scratch, double max_distance, std::span<const float> bound,
                                std::span<const std::uint32_t> origins) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // Distances up to `keep` are kept, so that those within max_distance come
  // out as an unlimited solve gives them (fim_margin).
  const double keep = max_distance + margin_;
  // The active vertices are taken nearest first, and one lowered after it
  // was taken is queued again: what the rounds reach, with each vertex
  // taken about once (in rounds, 20 to 50 times: minutes, not seconds, for
  // cheese's balls at quality's cutoff).
  ShortestFirstQueue queue(sources, distances, scratch, keep, bound, !origins.empty());
  std::vector<std::uint32_t>& origin = scratch.origin;
  for (std::uint32_t k = 0; k < sources.size(); ++k) origin[sources[k]] = origins.empty() ? k : origins[k];
  const bool several_sources = sources.size() > 1 || !origins.empty();
  const auto lower = [&](VertexId v, double candidate, std::uint32_t from) {
    if (!(candidate <= keep) || !(candidate < distances[v] * (1 - kLeastDrop)) || !queue.reopen(v, candidate)) return;
    origin[v] = from;
    queue.requeue(v);
  };
  // A point-source update reads only corners measured from the same source
  // (see fast_marching.cpp); edges may always lower.
  const auto reached = [&](VertexId other, VertexId x) {
    return distances[other] < kInfinity && (!several_sources || origin[other] == origin[x]);
  };
  const auto& offsets = mesh_.ring_offsets();
  const auto& neighbors = mesh_.ring_neighbors();
  while (const auto taken = queue.pop_next()) {
    const VertexId x = *taken;
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
  for (const VertexId v : scratch.touched) scratch.accepted[v] = distances[v] <= max_distance ? 1 : 0;
}

}  // namespace meshparticles
