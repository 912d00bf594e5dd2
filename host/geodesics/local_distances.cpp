#include "geodesics/local_distances.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>

#include "common/elapsed.hpp"
#include "common/progress.hpp"
#include "common/worker_threads.hpp"
#include "geodesics/solver_factory.hpp"

namespace meshparticles {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Below this many missing balls a prefetch computes them on the calling
// thread: starting threads would cost more than it saves.
constexpr std::size_t kParallelBatch = 64;
// Batches this large show a progress line; smaller ones once they have
// taken this long.
constexpr std::size_t kProgressBatch = 2000;
constexpr double kShowFewBallsAfter = 1.0;  // seconds
// The most queued balls a helper takes to the device at once: enough to
// fill it, few enough that a caller waiting for one of them is not kept long.
constexpr std::size_t kDeviceBatch = 256;

}  // namespace

std::optional<float> distance_in_ball(const Ball& ball, VertexId v) {
  const auto it = std::lower_bound(ball.vertices.begin(), ball.vertices.end(), v);
  if (it == ball.vertices.end() || *it != v) return std::nullopt;
  return ball.distances[std::size_t(it - ball.vertices.begin())];
}

void distances_to(VertexId v, std::span<const Ball* const> balls, std::span<float> out) {
  // 16 searches in flight: measured on the atrium's balls, fewer left
  // memory idle and more gained nothing.
  constexpr std::size_t kInFlight = 16;
  static constexpr VertexId kNoVertex = std::numeric_limits<VertexId>::max();  // stands in for an empty ball
  for (std::size_t first = 0; first < balls.size(); first += kInFlight) {
    const std::size_t count = std::min(kInFlight, balls.size() - first);
    std::array<const VertexId*, kInFlight> at;
    std::array<std::size_t, kInFlight> left;
    std::size_t widest = 1;
    for (std::size_t j = 0; j < count; ++j) {
      const auto& ids = balls[first + j]->vertices;
      at[j] = ids.empty() ? &kNoVertex : ids.data();
      left[j] = std::max<std::size_t>(ids.size(), 1);
      widest = std::max(widest, left[j]);
    }
    // Halve every range in step, without branches: at[j] ends on the last
    // id <= v (or the first id). A finished range (left 1) stays put.
    while (widest > 1) {
      for (std::size_t j = 0; j < count; ++j) {
        const std::size_t half = left[j] / 2;
        at[j] = at[j][half] <= v ? at[j] + half : at[j];
        left[j] -= half;
      }
      widest -= widest / 2;
    }
    for (std::size_t j = 0; j < count; ++j) {
      const Ball& ball = *balls[first + j];
      out[first + j] = *at[j] == v ? ball.distances[std::size_t(at[j] - ball.vertices.data())] : kInfinity;
    }
  }
}

float LocalDistances::symmetric_distance(const Ball& from_u, VertexId u, const Ball& from_v, VertexId v) {
  const auto there = distance_in_ball(from_u, v);
  if (!there) return kInfinity;
  const auto back = distance_in_ball(from_v, u);
  if (!back) return kInfinity;
  return symmetric_mean(*there, *back);
}

LocalDistances::LocalDistances(const SurfaceMesh& mesh, const Settings& settings)
    : vertex_count_(mesh.vertex_count()),
      settings_(settings),
      solver_(make_geodesic_solver(mesh, settings.method, cores_or(settings.threads))),
      device_balls_(settings.device && settings.method == GeodesicMethod::fast_iterative
                        ? std::make_unique<DeviceBallSolver>(
                              mesh, static_cast<const FastIterativeMethod&>(*solver_), *settings.device,
                              cores_or(settings.threads))
                        : nullptr),
      cache_(mesh.vertex_count(), settings.cache_bytes),
      queue_(mesh.vertex_count()) {}

LocalDistances::~LocalDistances() { queue_.stop(mutex_); }

float LocalDistances::distance(VertexId u, VertexId v) const {
  const auto from_u = ball(u);
  const auto from_v = ball(v);
  return symmetric_distance(*from_u, u, *from_v, v);
}

void LocalDistances::distances_from(VertexId u, std::span<const VertexId> targets, std::span<float> out) const {
  prefetch(targets);
  const auto from_u = ball(u);
  for (std::size_t k = 0; k < targets.size(); ++k) {
    // Only targets in u's ball can be near: the rest need no ball of their own.
    out[k] = distance_in_ball(*from_u, targets[k]) ? symmetric_distance(*from_u, u, *ball(targets[k]), targets[k])
                                                    : kInfinity;
  }
}

void LocalDistances::for_each_marked_within(VertexId u, float radius, std::span<const std::uint8_t> marked,
                                            VertexId first, const std::function<void(VertexId, float)>& visit) const {
  const auto from_u = ball(u);
  std::vector<VertexId> near;
  std::vector<float> there;  // d_u(v)
  const auto& ids = from_u->vertices;  // increasing
  for (auto it = std::lower_bound(ids.begin(), ids.end(), first); it != ids.end(); ++it) {
    if (marked[*it]) {
      near.push_back(*it);
      there.push_back(from_u->distances[std::size_t(it - ids.begin())]);
    }
  }
  prefetch(near);
  std::vector<std::shared_ptr<const Ball>> near_balls;
  for (const VertexId v : near) near_balls.push_back(ball(v));
  for_each_distance_to(
      u, near.size(), [&](std::size_t k) { return near_balls[k].get(); },
      [&](std::size_t k, float back) {
        const float d = symmetric_mean(there[k], back);
        if (d <= radius) visit(near[k], d);
      });
}

std::shared_ptr<const Ball> LocalDistances::ball(VertexId u) const {
  std::unique_lock lock(mutex_);
  cache_.touch(u);
  if (const auto& held = cache_.held(u)) return held;
  const auto started = std::chrono::steady_clock::now();
  // A helper is solving u: rather than wait idle, solve what is queued after it.
  while (queue_.being_solved(u)) {
    if (const auto other = queue_.take(cache_)) {
      const VertexId taken[] = {*other};
      solve_taken(taken, lock, scratch_, &scratch_mutex_);
    } else {
      queue_.wait_for_ball(lock);
    }
  }
  std::shared_ptr<const Ball> found = cache_.held(u);
  if (!found) {
    queue_.claim(u);  // a waiting u is ours now: the helpers pass it by
    const VertexId taken[] = {u};
    found = solve_taken(taken, lock, scratch_, &scratch_mutex_).front();
  }
  statistics_.seconds += seconds_since(started);
  return found;
}

std::vector<std::shared_ptr<const Ball>> LocalDistances::solve_taken(std::span<const VertexId> taken,
                                                                     std::unique_lock<std::mutex>& lock,
                                                                     SolverScratch& scratch,
                                                                     std::mutex* scratch_guard) const {
  lock.unlock();
  Solved solved;
  try {
    std::unique_lock<std::mutex> guard;  // never held together with mutex_
    if (scratch_guard) guard = std::unique_lock(*scratch_guard);
    solved = solve_now(taken, scratch);
  } catch (...) {  // out of memory: nobody may wait for them forever
    lock.lock();
    queue_.finish(taken);
    throw;
  }
  lock.lock();
  std::vector<std::shared_ptr<const Ball>> computed;
  for (std::size_t k = 0; k < taken.size(); ++k) {
    computed.push_back(std::make_shared<const Ball>(std::move(solved.balls[k])));
    keep(taken[k], computed.back());
  }
  statistics_.balls_on_device += solved.on_device;
  evict();
  queue_.finish(taken);
  return computed;
}

LocalDistances::Solved LocalDistances::solve_now(std::span<const VertexId> vertices, SolverScratch& scratch,
                                                 const std::function<void(std::size_t)>& progress) const {
  Solved solved;
  if (device_balls_) {
    const std::lock_guard device_lock(device_mutex_);
    const std::size_t on_host_before = device_balls_->statistics().solved_on_host;
    solved.balls = device_balls_->solve_balls(vertices, settings_.radius, progress);
    solved.on_device = vertices.size() - (device_balls_->statistics().solved_on_host - on_host_before);
    return solved;
  }
  for (const VertexId v : vertices) solved.balls.push_back(solver_->solve_ball(v, settings_.radius, scratch));
  return solved;
}

unsigned LocalDistances::threads() const {
  return cores_or(settings_.threads);
}

void LocalDistances::request(std::span<const VertexId> vertices) const {
  if (threads() < 2) return;  // no helper: ball() solves each when it is read
  {
    const std::lock_guard lock(mutex_);
    for (const VertexId v : vertices) {
      if (!cache_.held(v) && queue_.idle(v)) queue_.add(v);
    }
    // With a device one helper keeps it busy, a batch at a time; more would queue for it.
    queue_.start_helpers(device_balls_ ? 1 : threads() - 1, [this] { help(); });
  }
  queue_.work_added();
}

void LocalDistances::help() const {
  SolverScratch scratch;
  std::unique_lock lock(mutex_);
  while (queue_.wait_for_work(lock)) {
    // The device solves many balls in the time of one: a helper takes a batch to it.
    std::vector<VertexId> taken;
    while (taken.size() < (device_balls_ ? kDeviceBatch : 1)) {
      const auto v = queue_.take(cache_);
      if (!v) break;
      taken.push_back(*v);
    }
    if (taken.empty()) continue;
    const auto started = std::chrono::steady_clock::now();
    try {
      solve_taken(taken, lock, scratch, nullptr);
    } catch (...) {  // out of memory: left to ball(), which meets it again on the caller's thread
    }
    statistics_.background_seconds += seconds_since(started);
  }
}

void LocalDistances::prefetch(std::span<const VertexId> vertices) const {
  std::vector<VertexId> missing;
  {
    const std::lock_guard lock(mutex_);
    for (const VertexId v : vertices) {
      cache_.touch(v);  // wanted now: not the next to go
      if (!cache_.held(v)) missing.push_back(v);
    }
  }
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  if (missing.empty()) return;
  const auto started = std::chrono::steady_clock::now();
  // Fewer balls are usually quick, and shown only where they are not (a
  // wide radius on a fine mesh: 1,024 balls of cheese's 93k vertices at 7
  // spacings take 9 s by fmm, minutes by fim).
  ProgressLine progress("distance balls", missing.size(), settings_.quiet,
                        missing.size() < kProgressBatch ? kShowFewBallsAfter : 0.0);
  if (device_balls_) {
    solve_on_device(missing, progress);
    progress.finish();
    const std::lock_guard lock(mutex_);
    statistics_.seconds += seconds_since(started);
    evict();
    return;
  }
  const unsigned threads = missing.size() < kParallelBatch ? 1 : this->threads();
  std::atomic<std::size_t> next{0}, done{0};
  std::exception_ptr failure;
  std::condition_variable handed_out;  // every ball taken: the caller stops waiting and joins
  const auto work = [&] {
    try {
      SolverScratch scratch;
      for (std::size_t k = next++; k < missing.size(); k = next++) {
        auto computed = std::make_shared<const Ball>(solver_->solve_ball(missing[k], settings_.radius, scratch));
        const std::lock_guard lock(mutex_);
        keep(missing[k], std::move(computed));
        ++done;
      }
    } catch (...) {  // out of memory: rethrown on the calling thread, the others stop
      const std::lock_guard lock(mutex_);
      if (!failure) failure = std::current_exception();
      next = missing.size();
    }
    const std::lock_guard lock(mutex_);  // so that the caller is waiting, or sees `next` before it waits
    handed_out.notify_all();
  };
  if (threads == 1) {
    work();
  } else {
    WorkerThreads workers(threads, [&](unsigned) { work(); });
    if (workers.started() == 0) work();  // no thread could start: this one does it all
    try {
      // Woken when a worker runs out of balls (a sleep of its own here kept
      // the caller up to 0.1 s after the last: most of a measurement of a
      // few hundred particles), else every 0.1 s for the progress line.
      const auto all_taken = [&] { return done >= missing.size() || next >= missing.size(); };
      while (!all_taken()) {
        progress.update(done);
        std::unique_lock lock(mutex_);
        handed_out.wait_for(lock, std::chrono::milliseconds(100), all_taken);
      }
    } catch (...) {  // interrupted: the workers stop at their next ball, the balls made are kept
      next = missing.size();
      throw;  // WorkerThreads joins them
    }
    workers.join();
  }
  progress.update(done);
  progress.finish();
  if (failure) std::rethrow_exception(failure);
  const std::lock_guard lock(mutex_);
  statistics_.seconds += seconds_since(started);
  evict();
}

void LocalDistances::solve_on_device(std::span<const VertexId> missing, ProgressLine& progress) const {
  constexpr std::size_t kPiece = std::size_t{1} << 16;  // balls between progress updates
  SolverScratch unused;  // the device's solver keeps its own
  for (std::size_t first = 0; first < missing.size(); first += kPiece) {
    const auto piece = missing.subspan(first, std::min(kPiece, missing.size() - first));
    Solved solved = solve_now(piece, unused, [&](std::size_t done) { progress.update(first + done); });
    const std::lock_guard lock(mutex_);
    for (std::size_t k = 0; k < piece.size(); ++k) {
      keep(piece[k], std::make_shared<const Ball>(std::move(solved.balls[k])));
    }
    statistics_.balls_on_device += solved.on_device;
    progress.update(first + piece.size());
  }
}

void LocalDistances::keep(VertexId u, std::shared_ptr<const Ball> ball) const {
  ++statistics_.balls_computed;  // every solve, one made twice too: the work done
  statistics_.entries_computed += ball->vertices.size();
  cache_.insert(u, std::move(ball));  // a prefetch solved it beside a helper: the first stays
}

void LocalDistances::evict() const { statistics_.balls_evicted += cache_.evict_to_budget(); }

LocalDistances::Statistics LocalDistances::statistics() const {
  const std::lock_guard lock(mutex_);
  Statistics statistics = statistics_;
  statistics.peak_bytes = cache_.peak_bytes();
  return statistics;
}

}  // namespace meshparticles
