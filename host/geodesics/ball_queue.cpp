#include "geodesics/ball_queue.hpp"

#include <system_error>

namespace meshparticles {

BallQueue::BallQueue(std::size_t vertex_count) : state_(vertex_count, State::idle) {}

void BallQueue::add(VertexId v) {
  state_[v] = State::waiting;
  waiting_.push_back(v);
}

std::optional<VertexId> BallQueue::take(const BallCache& cache) {
  while (!waiting_.empty()) {
    const VertexId v = waiting_.front();
    waiting_.pop_front();
    if (state_[v] != State::waiting) continue;  // the caller took it
    if (cache.held(v)) {  // a prefetch solved it meanwhile
      state_[v] = State::idle;
      continue;
    }
    state_[v] = State::solving;
    return v;
  }
  return std::nullopt;
}

void BallQueue::finish(std::span<const VertexId> taken) {
  for (const VertexId v : taken) state_[v] = State::idle;
  ball_ready_.notify_all();
}

bool BallQueue::wait_for_work(std::unique_lock<std::mutex>& lock) {
  work_ready_.wait(lock, [&] { return stopping_ || !waiting_.empty(); });
  return !stopping_;
}

void BallQueue::start_helpers(std::size_t count, const std::function<void()>& help) {
  try {
    while (helpers_.size() < count) helpers_.emplace_back(help);
  } catch (const std::system_error&) {  // no room for another thread: the caller solves what no helper takes
  }
}

void BallQueue::stop(std::mutex& mutex) {
  {
    const std::lock_guard lock(mutex);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (auto& helper : helpers_) helper.join();
}

}  // namespace meshparticles
