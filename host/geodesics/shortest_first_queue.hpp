#pragma once
// The acceptance order both solvers share: a binary heap over tentative
// distances, one entry per queued vertex (a lowered vertex moves up in
// place, so the heap stays the size of the front and no stale entry is
// ever popped). An entry is one 64-bit integer, float32 distance bits above
// the vertex id: for non-negative floats the bit pattern orders like the
// value, so the heap compares plain integers, and ties between vertices
// break by id. The distances themselves stay double.
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>

#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class ShortestFirstQueue {
 public:
  // Queues the sources at distance 0, or at the distances they already
  // have when `at_given_distances` (the caller noted them in
  // scratch.touched). Expects every other distance +inf, no vertex accepted
  // and none queued where the march goes (GeodesicSolver::march); records
  // each vertex given a distance in scratch.touched. Vertices farther than
  // `max_distance` are never accepted, and none is given a distance of
  // `bound[v]` or more (no bound when empty).
  ShortestFirstQueue(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                     double max_distance, std::span<const float> bound, bool at_given_distances = false)
      : distances_(distances),
        heap_(scratch.heap),
        slot_(scratch.heap_slot),
        accepted_(scratch.accepted),
        touched_(scratch.touched),
        max_distance_(max_distance),
        bound_(bound) {
    heap_.clear();
    for (const VertexId source : sources) {
      if (!at_given_distances) {
        if (distances_[source] != 0.0) touched_.push_back(source);
        distances_[source] = 0.0;
      }
      requeue(source);
    }
  }
  // Leaves the scratch clean: the vertices still queued (beyond the
  // stopping distance) are no longer.
  ~ShortestFirstQueue() {
    for (const std::uint64_t entry : heap_) slot_[vertex_of(entry)] = kNotQueued;
    heap_.clear();
  }
  ShortestFirstQueue(const ShortestFirstQueue&) = delete;
  ShortestFirstQueue& operator=(const ShortestFirstQueue&) = delete;

  // The closest vertex not yet accepted, now accepted; none when all are
  // done or the next one lies beyond the stopping distance.
  std::optional<VertexId> pop_next() {
    if (heap_.empty()) return std::nullopt;
    const VertexId vertex = vertex_of(heap_.front());
    if (distances_[vertex] > max_distance_) return std::nullopt;
    slot_[vertex] = kNotQueued;
    const std::uint64_t last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) sift_down(0, last);
    accepted_[vertex] = 1;
    return vertex;
  }

  bool is_accepted(VertexId v) const { return accepted_[v] != 0; }

  // The closest queued vertex, if any: what pop_next() takes next unless a
  // distance is lowered below it first (or it lies beyond the stopping
  // distance). A hint for prefetching; nothing is decided by it.
  std::optional<VertexId> front() const {
    if (heap_.empty()) return std::nullopt;
    return vertex_of(heap_.front());
  }

  // Lowers v's tentative distance to `candidate` if that is shorter.
  void offer(VertexId v, double candidate) {
    if (lower(v, candidate)) requeue(v);
  }

  // offer() in two steps, for a solver that lowers a vertex several times
  // before queueing it once: lower() returns whether v's distance dropped.
  bool lower(VertexId v, double candidate) {
    // One branch for both tests: which of them fails is hard to predict.
    return would_lower(v, candidate) && set_within_bound(v, candidate);
  }
  // lower() for a label-correcting solver (fast_iterative.cpp): v may be
  // accepted already, and is then no longer, to be queued again.
  bool reopen(VertexId v, double candidate) {
    if (!(candidate < distances_[v]) || !set_within_bound(v, candidate)) return false;
    accepted_[v] = 0;
    return true;
  }
  // lower()'s first test alone, without a branch (| on whole numbers, not ||).
  bool would_lower(VertexId v, double candidate) const {
    return (unsigned(accepted_[v] != 0) | unsigned(candidate >= distances_[v])) == 0;
  }
  // Queues v at its distance, or moves it up to it if queued already (a
  // distance only ever drops).
  void requeue(VertexId v) {
    const float key = float(distances_[v]);
    std::uint32_t key_bits;
    std::memcpy(&key_bits, &key, sizeof key);
    const std::uint64_t entry = (std::uint64_t(key_bits) << 32) | v;
    if (slot_[v] == kNotQueued) {
      heap_.push_back(entry);
      sift_up(std::uint32_t(heap_.size() - 1), entry);
    } else {
      sift_up(slot_[v], entry);
    }
  }

 private:
  static constexpr std::uint32_t kNotQueued = SolverScratch::kNotQueued;
  static VertexId vertex_of(std::uint64_t entry) { return VertexId(entry & 0xFFFFFFFFu); }

  // v's distance set to `candidate` (below it), unless the bound forbids.
  bool set_within_bound(VertexId v, double candidate) {
    if (!bound_.empty() && candidate >= double(bound_[v])) return false;  // no nearer than the bound says
    if (distances_[v] == std::numeric_limits<double>::infinity()) touched_.push_back(v);
    distances_[v] = candidate;
    return true;
  }

  void place(std::uint32_t at, std::uint64_t entry) {
    heap_[at] = entry;
    slot_[vertex_of(entry)] = at;
  }
  void sift_up(std::uint32_t at, std::uint64_t entry) {
    while (at > 0) {
      const std::uint32_t parent = (at - 1) / 2;
      if (heap_[parent] <= entry) break;
      place(at, heap_[parent]);
      at = parent;
    }
    place(at, entry);
  }
  // Removes the root: its hole sinks to a leaf along the smaller children,
  // then `entry` (the old last leaf, usually large) rises from there. Half
  // the comparisons of a plain sift-down, and the choice of child is a
  // conditional move, not a branch.
  void sift_down(std::uint32_t at, std::uint64_t entry) {
    const auto size = std::uint32_t(heap_.size());
    for (std::uint32_t child = 2 * at + 1; child < size; child = 2 * at + 1) {
      if (child + 1 < size) child += heap_[child + 1] < heap_[child] ? 1 : 0;
      place(at, heap_[child]);
      at = child;
    }
    sift_up(at, entry);
  }

  std::span<double> distances_;
  std::vector<std::uint64_t>& heap_;
  std::vector<std::uint32_t>& slot_;
  std::vector<unsigned char>& accepted_;
  std::vector<VertexId>& touched_;
  double max_distance_;
  std::span<const float> bound_;
};

}  // namespace meshparticles
