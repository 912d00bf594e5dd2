#include "geodesics/fast_marching.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geodesics/point_source_update.hpp"
#include "geodesics/shortest_first_queue.hpp"

namespace meshparticles {

namespace {

constexpr std::uint32_t kBatch = 16;
constexpr std::size_t kCacheLine = 64;
constexpr std::size_t kStencilLinesFetched = 4;  // 8 triangles
constexpr std::size_t kVirtualLinesFetched = 1;  // 3 virtual updates

}  // namespace

FastMarching::FastMarching(const SurfaceMesh& mesh, unsigned threads)
    : GeodesicSolver(mesh.vertex_count()),
      mesh_(mesh),
      edge_lengths_(ring_edge_lengths(mesh)),
      stencils_(build_triangle_stencils(mesh, threads)) {
  const auto& ring = mesh.ring_offsets();
  starts_.reserve(ring.size());
  for (std::size_t v = 0; v < ring.size(); ++v) {
    starts_.push_back({ring[v], stencils_.triangle_offsets[v], stencils_.virtual_offsets[v], 0});
  }
  stencils_.triangle_offsets = {};
  stencils_.virtual_offsets = {};
}

void FastMarching::march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                         double max_distance, std::span<const float> bound,
                         std::span<const std::uint32_t> origins) const {
  // One source (every ball, every farthest sample): every distance comes
  // from it, and the per-vertex origin bookkeeping is skipped.
  if (sources.size() == 1 && origins.empty()) {
    march_from<true>(sources, distances, scratch, max_distance, bound, origins);
  } else {
    march_from<false>(sources, distances, scratch, max_distance, bound, origins);
  }
}

template <bool kOneSource>
void FastMarching::march_from(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                              double max_distance, std::span<const float> bound,
                              std::span<const std::uint32_t> origins) const {
  ShortestFirstQueue queue(sources, distances, scratch, max_distance, bound, !origins.empty());
  const auto& neighbors = mesh_.ring_neighbors();
  const auto& triangles = stencils_.triangles;
  const auto& virtuals = stencils_.virtual_updates;
  // Which source each vertex's distance comes from. A point-source update
  // places one virtual source from d(X) and d(Y); where two sources' fronts
  // meet, X and Y measure from different sources and that point would be
  // nowhere real (measured: a quarter of an edge too short). So triangles
  // update only from corners of the same source; edges always may.
  // (Read only for accepted vertices, each of which was set when lowered.)
  std::vector<std::uint32_t>& origin = scratch.origin;
  if constexpr (!kOneSource) {
    for (std::uint32_t k = 0; k < sources.size(); ++k) origin[sources[k]] = origins.empty() ? k : origins[k];
  }
  const auto same_origin = [&](VertexId a, VertexId b) { return kOneSource || origin[a] == origin[b]; };
  // Vertices lowered while processing one accepted vertex, queued once each
  // afterwards (an edge update is often bettered by a triangle update).
  std::vector<VertexId>& lowered = scratch.lowered;
  while (auto accepted = queue.pop_next()) {
    const VertexId x = *accepted;
    const double dx = distances[x];
    const UpdateStarts here = starts_[x], end = starts_[x + 1];
    lowered.clear();
    // A vertex's stencils (about 200 bytes, read in acceptance order) miss
    // the cache on any mesh past a few thousand vertices. The queue's front
    // is the next vertex accepted unless this one lowers a neighbour below
    // it: its stencils, virtual updates, ring and edge lengths are fetched
    // while this one is processed. (Pointers, not references: it may have
    // no triangles and be the last vertex.)
    if (const auto next = queue.front()) {
      const UpdateStarts& its = starts_[*next];
      const auto* stencils = reinterpret_cast<const char*>(triangles.data() + its.triangles);
      for (std::size_t line = 0; line < kStencilLinesFetched; ++line) __builtin_prefetch(stencils + kCacheLine * line);
      const auto* virtual_updates = reinterpret_cast<const char*>(virtuals.data() + its.virtuals);
      for (std::size_t line = 0; line < kVirtualLinesFetched; ++line) {
        __builtin_prefetch(virtual_updates + kCacheLine * line);
      }
      __builtin_prefetch(neighbors.data() + its.ring);
      __builtin_prefetch(edge_lengths_.data() + its.ring);
    }
    // Along edges: exact next to the source, an upper bound elsewhere. The
    // few neighbours this lowers (about one in five) are found without a
    // branch, then lowered.
    for (std::uint32_t first = here.ring; first < end.ring; first += kBatch) {
      std::array<std::uint32_t, kBatch> nearer;
      std::uint32_t nearer_count = 0;
      for (std::uint32_t k = first; k < std::min(end.ring, first + kBatch); ++k) {
        nearer[nearer_count] = k;
        nearer_count += std::uint32_t(queue.would_lower(neighbors[k], dx + edge_lengths_[k]));
      }
      for (std::uint32_t r = 0; r < nearer_count; ++r) {
        const std::uint32_t k = nearer[r];
        if (queue.lower(neighbors[k], dx + edge_lengths_[k])) {
          lowered.push_back(neighbors[k]);  // distinct: a ring
          if constexpr (!kOneSource) origin[neighbors[k]] = origin[x];
        }
      }
    }
    const auto lower_and_note = [&](VertexId v, double candidate) {
      if (!queue.lower(v, candidate)) return;
      if constexpr (!kOneSource) origin[v] = origin[x];
      if (std::find(lowered.begin(), lowered.end(), v) == lowered.end()) lowered.push_back(v);
    };
    // Across each triangle with exactly one other corner accepted. Which
    // triangles those are is collected first without a branch (whether a
    // corner is accepted is a coin toss to the predictor), 16 at a time.
    for (std::uint32_t first = here.triangles; first < end.triangles; first += kBatch) {
      std::array<std::uint32_t, kBatch> ready;  // 2 * (k - first) + whether corner a is the accepted one
      std::uint32_t ready_count = 0;
      for (std::uint32_t k = first; k < std::min(end.triangles, first + kBatch); ++k) {
        const TriangleAtVertex& t = triangles[k];
        const bool a_accepted = queue.is_accepted(t.a), b_accepted = queue.is_accepted(t.b);
        ready[ready_count] = 2 * (k - first) + std::uint32_t(a_accepted);
        ready_count += std::uint32_t(a_accepted != b_accepted);
      }
      for (std::uint32_t r = 0; r < ready_count; ++r) {
        const TriangleAtVertex& t = triangles[first + ready[r] / 2];
        const bool a_accepted = ready[r] % 2 != 0;
        const VertexId target = a_accepted ? t.b : t.a, other = a_accepted ? t.a : t.b;
        if (!same_origin(other, x)) continue;
        lower_and_note(target, point_source_update(a_accepted ? t.b_from_a : t.a_from_b, dx, distances[other]));
      }
    }
    // Across unfolded virtual triangles at obtuse corners.
    for (std::uint32_t k = here.virtuals; k < end.virtuals; ++k) {
      const VirtualUpdate& u = virtuals[k];
      if (queue.is_accepted(u.target) || !queue.is_accepted(u.other) || !same_origin(u.other, x)) continue;
      lower_and_note(u.target, point_source_update(u.frame, dx, distances[u.other]));
    }
    for (VertexId v : lowered) queue.requeue(v);
  }
}

}  // namespace meshparticles
