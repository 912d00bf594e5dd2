#pragma once
// The local store: distances only between vertices near each other, for
// meshes whose V x V table would not fit. Each vertex's ball - the vertices
// within the store's radius and their distances from it - is computed on
// demand by a solve stopped at the radius, on all cores or the device, and
// kept in a cache bounded in bytes (ball_cache); balls asked for ahead of
// need are solved by helper threads (ball_queue).
//
// The distance between two vertices is the mean of the two one-sided
// values, each read from the other's ball: exactly what the dense table
// holds (its rows are the same solves, averaged the same way), wherever each
// vertex lies in the other's ball. Beyond that the store answers +inf:
// symmetric, like every distance the particle system reads.
#include <array>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "common/progress.hpp"
#include "geodesics/ball_cache.hpp"
#include "geodesics/ball_queue.hpp"
#include "geodesics/device_balls.hpp"
#include "geodesics/distance_store.hpp"
#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class LocalDistances final : public DistanceStore {
 public:
  struct Settings {
    double radius = 0;          // mesh units
    GeodesicMethod method = GeodesicMethod::fast_marching;
    std::uint64_t cache_bytes = 0;  // balls kept at most; the least recently used go first
    unsigned threads = 0;           // 0: all cores
    bool quiet = false;             // no progress line
    // With the fast iterative method: the device that solves the balls of
    // prefetch() and of request()'s helpers (device_balls.hpp), many at
    // once, and single balls too; those too big for it are solved on the
    // host by the same method.
    std::optional<DeviceDescription> device;
  };

  struct Statistics {
    std::size_t balls_computed = 0;
    std::uint64_t entries_computed = 0;  // over all balls computed: their mean size is this / balls_computed
    double seconds = 0;                  // the caller's time on balls: computing them or waiting for them
    double background_seconds = 0;       // spent by the helpers of request(), beside the caller
    std::size_t balls_evicted = 0;
    std::uint64_t peak_bytes = 0;  // of the cache
    std::size_t balls_on_device = 0;  // of balls_computed
  };

  LocalDistances(const SurfaceMesh& mesh, const Settings& settings);
  ~LocalDistances() override;
  LocalDistances(const LocalDistances&) = delete;
  LocalDistances& operator=(const LocalDistances&) = delete;

  std::size_t vertex_count() const override { return vertex_count_; }
  float distance(VertexId u, VertexId v) const override;
  void distances_from(VertexId u, std::span<const VertexId> targets, std::span<float> out) const override;
  void for_each_marked_within(VertexId u, float radius, std::span<const std::uint8_t> marked, VertexId first,
                              const std::function<void(VertexId, float)>& visit) const override;
  float reach() const override { return float(settings_.radius); }
  const LocalDistances* local_balls() const override { return this; }
  // The threads it solves balls on (Settings::threads, 0 resolved to the cores).
  unsigned threads() const;
  // The solver its balls come from, built for its mesh: for a ball of another radius.
  const GeodesicSolver& solver() const { return *solver_; }

  // Computes the balls of `vertices` the cache does not hold, on all cores
  // (with a progress line when there are many), and keeps them.
  void prefetch(std::span<const VertexId> vertices) const;

  // Queues the balls of `vertices` the cache does not hold for helper
  // threads (one fewer than the store's threads; one, taking batches to
  // the device, when the store has one) and returns at once: the
  // caller goes on with other work while they are solved. ball() of a
  // queued vertex solves it at once if no helper has begun it; if one has,
  // it solves the balls queued after it until that one is done.
  void request(std::span<const VertexId> vertices) const;

  // u's ball (computed now if the cache does not hold it). Holding the
  // pointer keeps the ball alive whatever the cache evicts meanwhile.
  std::shared_ptr<const Ball> ball(VertexId u) const;

  // d(u, v) from u's and v's balls: the mean of the one-sided values, +inf
  // unless each lies in the other's ball.
  static float symmetric_distance(const Ball& from_u, VertexId u, const Ball& from_v, VertexId v);
  // That mean, of the one-sided values d_u(v) and d_v(u) (+inf for one not
  // in the ball): as symmetrize_by_averaging, the same bits as the table.
  static float symmetric_mean(float from_u_to_v, float from_v_to_u) { return 0.5f * (from_u_to_v + from_v_to_u); }

  Statistics statistics() const;

 private:
  struct Solved {
    std::vector<Ball> balls;
    std::size_t on_device = 0;
  };
  // The balls of `vertices`, in their order, without mutex_: on the device
  // when the store has one (all in one call; `progress` hears how many are
  // done), else one by one on this thread.
  Solved solve_now(std::span<const VertexId> vertices, SolverScratch& scratch,
                   const std::function<void(std::size_t)>& progress = {}) const;
  // prefetch()'s balls on the device, kept as they come.
  void solve_on_device(std::span<const VertexId> missing, ProgressLine& progress) const;
  // Solves `taken` (claimed from the queue) with `lock` on mutex_ released
  // meanwhile, under `scratch_guard` if given, and keeps them; `lock` is
  // held again on return, also when the solve throws.
  std::vector<std::shared_ptr<const Ball>> solve_taken(std::span<const VertexId> taken,
                                                       std::unique_lock<std::mutex>& lock, SolverScratch& scratch,
                                                       std::mutex* scratch_guard) const;
  void help() const;  // a helper thread of request()
  // With mutex_ held: counts a solve and caches its ball; evicts to the budget.
  void keep(VertexId u, std::shared_ptr<const Ball> ball) const;
  void evict() const;

  std::size_t vertex_count_;
  Settings settings_;
  std::unique_ptr<GeodesicSolver> solver_;
  mutable std::mutex device_mutex_;
  std::unique_ptr<DeviceBallSolver> device_balls_;  // under device_mutex_

  // Guards the cache, the queue and the statistics together.
  mutable std::mutex mutex_;
  mutable BallCache cache_;
  mutable BallQueue queue_;  // helpers start with the first request and stop with the store
  mutable Statistics statistics_;  // but peak_bytes, which the cache keeps
  mutable std::mutex scratch_mutex_;
  mutable SolverScratch scratch_;  // for balls computed one at a time, outside mutex_
};

// The one-sided distance from the ball's source to v, if v is in the ball.
std::optional<float> distance_in_ball(const Ball& ball, VertexId v);

// The same for many balls at once: out[k] is the distance from balls[k]'s
// source to v, +inf where v is not inside. The searches advance in step, a
// group at a time, so that their cache misses overlap: one search alone
// waits on memory at nearly every step (~180 ns on a big mesh).
void distances_to(VertexId v, std::span<const Ball* const> balls, std::span<float> out);

// Calls visit(k, d) for each k < count where ball_of(k) gives a ball (not
// null), d being the distance from that ball's source to v (+inf where v is
// not inside), through distances_to() in batches.
template <typename BallOf, typename Visit>
void for_each_distance_to(VertexId v, std::size_t count, BallOf ball_of, Visit visit) {
  constexpr std::size_t kBatch = 128;
  std::array<const Ball*, kBatch> balls;
  std::array<std::size_t, kBatch> indices;
  std::array<float, kBatch> found;
  std::size_t filled = 0;
  const auto answer = [&] {
    distances_to(v, std::span(balls.data(), filled), std::span(found.data(), filled));
    for (std::size_t j = 0; j < filled; ++j) visit(indices[j], found[j]);
    filled = 0;
  };
  for (std::size_t k = 0; k < count; ++k) {
    if (const Ball* ball = ball_of(k)) {
      balls[filled] = ball;
      indices[filled] = k;
      if (++filled == kBatch) answer();
    }
  }
  answer();
}

}  // namespace meshparticles
