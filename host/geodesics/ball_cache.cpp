#include "geodesics/ball_cache.hpp"

#include <algorithm>

namespace meshparticles {

BallCache::BallCache(std::size_t vertex_count, std::uint64_t budget_bytes)
    : budget_bytes_(budget_bytes), balls_(vertex_count), last_used_(vertex_count, 0) {}

void BallCache::insert(VertexId u, std::shared_ptr<const Ball> ball) {
  if (balls_[u]) return;
  bytes_ += ball->bytes();
  peak_bytes_ = std::max(peak_bytes_, bytes_);
  balls_[u] = std::move(ball);
  cached_.push_back(u);
}

// Evicts until the cache is a quarter under its budget, so that evictions
// come in batches rather than one per ball.
std::size_t BallCache::evict_to_budget() {
  if (bytes_ <= budget_bytes_) return 0;
  std::sort(cached_.begin(), cached_.end(), [&](VertexId a, VertexId b) { return last_used_[a] < last_used_[b]; });
  const std::uint64_t target = budget_bytes_ / 4 * 3;
  std::size_t evicted = 0;
  while (evicted < cached_.size() && bytes_ > target) {
    const VertexId u = cached_[evicted++];
    bytes_ -= balls_[u]->bytes();
    balls_[u].reset();
  }
  cached_.erase(cached_.begin(), cached_.begin() + std::ptrdiff_t(evicted));
  return evicted;
}

}  // namespace meshparticles
