#pragma once
// The balls a local store holds, bounded in bytes: the least recently used
// go first. Not thread-safe: its owner calls it under its own lock, the one
// that also guards the helpers' queue (local_distances).
#include <cstdint>
#include <memory>
#include <vector>

#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class BallCache {
 public:
  BallCache(std::size_t vertex_count, std::uint64_t budget_bytes);

  // u's ball, or null when not held.
  const std::shared_ptr<const Ball>& held(VertexId u) const { return balls_[u]; }
  // u is wanted now: not the next to go.
  void touch(VertexId u) { last_used_[u] = ++clock_; }
  // Keeps u's ball unless one is held already (then the first stays).
  void insert(VertexId u, std::shared_ptr<const Ball> ball);
  // Evicts the least recently used balls when over the budget; returns how many.
  std::size_t evict_to_budget();

  std::uint64_t peak_bytes() const { return peak_bytes_; }

 private:
  std::uint64_t budget_bytes_;
  std::vector<std::shared_ptr<const Ball>> balls_;  // per vertex; null when not held
  std::vector<std::uint64_t> last_used_;            // per vertex: the access clock when last read
  std::uint64_t clock_ = 0;
  std::uint64_t bytes_ = 0;
  std::uint64_t peak_bytes_ = 0;
  std::vector<VertexId> cached_;  // the vertices whose ball is held
};

}  // namespace meshparticles
