#pragma once
// The balls a local store was asked for ahead of need
// (LocalDistances::request) and the helper threads that solve them beside
// the caller. Every call but stop() is made with the owner's mutex held
// (the `lock` arguments are on it): that mutex also guards the ball cache,
// so whether a ball is held and whether it is queued change together.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "geodesics/ball_cache.hpp"

namespace meshparticles {

class BallQueue {
 public:
  explicit BallQueue(std::size_t vertex_count);

  // Neither waiting nor being solved.
  bool idle(VertexId v) const { return state_[v] == State::idle; }
  bool being_solved(VertexId v) const { return state_[v] == State::solving; }
  // Queues an idle v for the helpers.
  void add(VertexId v);
  // The next queued vertex nobody has begun and `cache` does not hold, now
  // marked as being solved by the caller.
  std::optional<VertexId> take(const BallCache& cache);
  // The caller solves v itself: a waiting v is passed by.
  void claim(VertexId v) { state_[v] = State::solving; }
  // `taken` are solved, or their solve failed: idle again, and whoever
  // waits for a ball wakes.
  void finish(std::span<const VertexId> taken);
  void wait_for_ball(std::unique_lock<std::mutex>& lock) { ball_ready_.wait(lock); }
  // Waits until a vertex is queued; false once the queue is stopping.
  bool wait_for_work(std::unique_lock<std::mutex>& lock);
  // Wakes the helpers after add().
  void work_added() { work_ready_.notify_all(); }

  // Starts helpers running `help` until `count` run, fewer when the system
  // refuses a thread (ulimit -v): the caller solves what no helper takes.
  void start_helpers(std::size_t count, const std::function<void()>& help);
  // Stops the helpers and joins them; `mutex` (the owner's) is not held.
  void stop(std::mutex& mutex);

 private:
  enum class State : std::uint8_t { idle, waiting, solving };

  std::vector<State> state_;  // per vertex
  std::deque<VertexId> waiting_;
  std::condition_variable work_ready_, ball_ready_;
  std::vector<std::thread> helpers_;
  bool stopping_ = false;
};

}  // namespace meshparticles
