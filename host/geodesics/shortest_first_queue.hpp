#pragma once
// The acceptance order both solvers share: a binary heap with lazy deletion
// (stale entries are skipped when popped) over tentative distances. An entry
// is one 64-bit integer, float32 distance bits above the vertex id: for
// non-negative floats the bit pattern orders like the value, so the heap
// compares plain integers. The distances themselves stay double.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <span>

#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class ShortestFirstQueue {
 public:
  // Queues the sources at distance 0. Expects every distance +inf and no
  // vertex accepted where the march goes (GeodesicSolver::march); records
  // each vertex given a distance in scratch.touched. Vertices farther than
  // `max_distance` are never accepted, and none is given a distance of
  // `bound[v]` or more (no bound when empty).
  ShortestFirstQueue(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                     double max_distance, std::span<const float> bound)
      : distances_(distances),
        heap_(scratch.heap),
        accepted_(scratch.accepted),
        touched_(scratch.touched),
        max_distance_(max_distance),
        bound_(bound) {
    heap_.clear();
    for (const VertexId source : sources) {
      if (distances_[source] != 0.0) touched_.push_back(source);
      distances_[source] = 0.0;
      requeue(source);
    }
  }

  // The closest vertex not yet accepted, now accepted; none when all are
  // done or the next one lies beyond the stopping distance.
  std::optional<VertexId> pop_next() {
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
      const auto vertex = VertexId(heap_.back() & 0xFFFFFFFFu);
      heap_.pop_back();
      // A vertex's latest (smallest) entry comes out first; later ones are stale.
      if (accepted_[vertex]) continue;
      if (distances_[vertex] > max_distance_) return std::nullopt;
      accepted_[vertex] = 1;
      return vertex;
    }
    return std::nullopt;
  }

  bool is_accepted(VertexId v) const { return accepted_[v] != 0; }

  // Lowers v's tentative distance to `candidate` if that is shorter.
  void offer(VertexId v, double candidate) {
    if (lower(v, candidate)) requeue(v);
  }

  // offer() in two steps, for a solver that lowers a vertex several times
  // before queueing it once: lower() returns whether v's distance dropped.
  bool lower(VertexId v, double candidate) {
    if (accepted_[v] || candidate >= distances_[v]) return false;
    if (!bound_.empty() && candidate >= double(bound_[v])) return false;  // no nearer than the bound says
    if (distances_[v] == std::numeric_limits<double>::infinity()) touched_.push_back(v);
    distances_[v] = candidate;
    return true;
  }
  void requeue(VertexId v) {
    const float key = float(distances_[v]);
    std::uint32_t key_bits;
    std::memcpy(&key_bits, &key, sizeof key);
    heap_.push_back((std::uint64_t(key_bits) << 32) | v);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  }

 private:
  std::span<double> distances_;
  std::vector<std::uint64_t>& heap_;
  std::vector<unsigned char>& accepted_;
  std::vector<VertexId>& touched_;
  double max_distance_;
  std::span<const float> bound_;
};

}  // namespace meshparticles
