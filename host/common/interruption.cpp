#include "common/interruption.hpp"

#include <atomic>
#include <chrono>

namespace meshparticles {

namespace {

std::atomic<InterruptionCheck> installed_check{nullptr};
// Per thread: two calls running at once (Python threads, each with its own
// cancel event) must not take each other's turns.
thread_local std::chrono::steady_clock::rep last_asked = 0;

}  // namespace

void set_interruption_check(InterruptionCheck check) {
  installed_check = check;
  last_asked = 0;  // a new check is asked at this thread's next update
}

void throw_if_interrupted() {
  const InterruptionCheck check = installed_check.load();
  if (!check) return;
  // The check may take a lock (Python's GIL): not on every update of a tight loop.
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  const auto interval = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::milliseconds(100));
  if (now - last_asked < interval.count()) return;
  last_asked = now;
  if (check()) throw Interrupted();
}

}  // namespace meshparticles
