#include "common/worker_pool.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace meshparticles {

namespace {

// How long a thread that waits (a helper for its next loop, the caller for
// its helpers) keeps checking before it sleeps: a run's loops come a
// fraction of a millisecond apart, and a sleeping thread took 40 us to wake
// on the 2-core test machine (a pool whose threads slept at once cost 87 us
// a loop of 16 pieces, more than threads started for it; checking first,
// 6 us: scripts/bench_worker_pool.sh).
constexpr std::chrono::microseconds kCheckFor{200};

// Waits until ready() holds, checking for kCheckFor, then sleeping on
// `wake` under `mutex` (whoever makes ready() true notifies under it).
template <typename Ready>
void wait_until(Ready ready, std::mutex& mutex, std::condition_variable& wake) {
  const auto until = std::chrono::steady_clock::now() + kCheckFor;
  for (unsigned k = 0; !ready(); ++k) {
    if (k % 64 == 63 && std::chrono::steady_clock::now() > until) {
      std::unique_lock lock(mutex);
      wake.wait(lock, ready);
      return;
    }
    std::this_thread::yield();
  }
}

class WorkerPool {
 public:
  bool run(unsigned helpers, const std::function<void(unsigned)>& share) {
    if (busy_.exchange(true, std::memory_order_acquire)) return false;
    {
      const std::lock_guard lock(mutex_);
      try {
        grow(helpers);
      } catch (...) {  // out of memory for the list: the pool stays usable
        busy_.store(false, std::memory_order_release);
        throw;
      }
      share_ = &share;
      const std::size_t assigned = std::min<std::size_t>(helpers, helpers_.size());
      running_.store(assigned, std::memory_order_relaxed);
      ++loop_;
      for (std::size_t k = 0; k < assigned; ++k) helpers_[k]->loop.store(loop_, std::memory_order_release);
    }
    wake_.notify_all();
    share(0);
    wait_until([&] { return running_.load(std::memory_order_acquire) == 0; }, mutex_, done_);
    busy_.store(false, std::memory_order_release);
    return true;
  }

 private:
  struct Helper {
    std::atomic<std::uint64_t> loop{0};  // the last loop it was given
    std::thread thread;                  // never joined: it waits for work until the process ends
  };

  // Up to `helpers` threads; fewer where the system refuses one.
  void grow(unsigned helpers) {
    helpers_.reserve(helpers);  // no throw below once a thread runs
    while (helpers_.size() < helpers) {
      auto helper = std::make_unique<Helper>();
      Helper& mine = *helper;
      try {
        helper->thread = std::thread([this, &mine, slot = unsigned(helpers_.size() + 1)] { serve(mine, slot); });
      } catch (const std::system_error&) {
        return;
      }
      helpers_.push_back(std::move(helper));
    }
  }

  // A helper runs share(slot) of each loop it is given. The caller changes
  // share_ only once every helper given its loop is done with it.
  void serve(const Helper& helper, unsigned slot) {
    std::uint64_t done = 0;
    for (;;) {
      wait_until([&] { return helper.loop.load(std::memory_order_acquire) != done; }, mutex_, wake_);
      done = helper.loop.load(std::memory_order_acquire);
      (*share_)(slot);
      if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        const std::lock_guard lock(mutex_);
        done_.notify_one();
      }
    }
  }

  std::atomic<bool> busy_{false};  // a caller's loop is running
  std::mutex mutex_;               // over growing, giving out a loop, and the sleeps
  std::condition_variable wake_, done_;
  std::vector<std::unique_ptr<Helper>> helpers_;
  const std::function<void(unsigned)>* share_ = nullptr;  // the loop in hand
  std::uint64_t loop_ = 0;                                 // loops given out
  std::atomic<std::size_t> running_{0};                    // helpers not done with it yet
};

}  // namespace

bool run_on_worker_pool(unsigned helpers, const std::function<void(unsigned)>& share) {
  // Never destroyed (its threads wait until the process ends; a static one
  // would be destroyed with them still waiting on it). After a fork the
  // child's copy has no threads: a new one, the old kept where a leak
  // checker sees it held (a death test's child exits through it).
  static std::mutex guard;
  static WorkerPool* pool = nullptr;
  static std::vector<WorkerPool*> forked_away;
  static pid_t owner = 0;
  WorkerPool* mine = nullptr;
  {
    const std::lock_guard lock(guard);
    if (!pool || owner != getpid()) {
      if (pool) forked_away.push_back(pool);
      pool = new WorkerPool;
      owner = getpid();
    }
    mine = pool;
  }
  return mine->run(helpers, share);
}

}  // namespace meshparticles
