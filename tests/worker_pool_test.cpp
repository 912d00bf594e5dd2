// Parallel loops run on threads kept for the process (common/worker_pool):
// every index once, on slots below the threads asked for, loop after loop;
// a loop inside a loop, loops from two threads at once, a loop that throws,
// and a loop in a forked child all finish; a loop that runs every piece
// rethrows its lowest failure.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"
#include "common/worker_pool.hpp"

namespace meshparticles::testing {
namespace {

// How many times each index ran in a loop of `count` on `threads`, and
// whether every slot was below `threads`.
std::vector<int> runs_of(std::size_t count, unsigned threads, bool& slots_below) {
  std::vector<std::atomic<int>> runs(count);
  std::atomic<bool> below{true};
  for_each_with_slot(count, threads, [&](std::size_t k, unsigned slot) {
    ++runs[k];
    if (slot >= threads) below = false;
  });
  slots_below = below;
  std::vector<int> plain;
  for (const auto& r : runs) plain.push_back(r);
  return plain;
}

TEST(WorkerPool, EveryIndexRunsOnceLoopAfterLoop) {
  for (int loop = 0; loop < 2000; ++loop) {
    const unsigned threads = 1 + loop % 6;  // the pool grows, and loops use fewer than it has
    bool slots_below = false;
    const std::vector<int> runs = runs_of(1 + loop % 97, threads, slots_below);
    ASSERT_TRUE(slots_below) << "loop " << loop;
    ASSERT_EQ(runs, std::vector<int>(runs.size(), 1)) << "loop " << loop;
  }
}

TEST(WorkerPool, HelpersRunShares) {
  // The pool's own threads run shares 1 .. helpers while the caller runs 0.
  std::vector<std::atomic<int>> ran(4);
  std::vector<std::thread::id> on(4);
  ASSERT_TRUE(run_on_worker_pool(3, [&](unsigned slot) {
    ++ran[slot];
    on[slot] = std::this_thread::get_id();
  }));
  for (unsigned slot = 0; slot < 4; ++slot) EXPECT_EQ(ran[slot], 1) << slot;
  EXPECT_EQ(on[0], std::this_thread::get_id());
  for (unsigned slot = 1; slot < 4; ++slot) EXPECT_NE(on[slot], std::this_thread::get_id()) << slot;
}

TEST(WorkerPool, ALoopInsideALoopRunsOnThreadsOfItsOwn) {
  std::vector<std::atomic<int>> runs(8 * 50);
  for_each_with_slot(8, 4, [&](std::size_t outer, unsigned) {
    for_each_with_slot(50, 3, [&](std::size_t inner, unsigned) { ++runs[outer * 50 + inner]; });
  });
  for (const auto& r : runs) ASSERT_EQ(r, 1);
}

TEST(WorkerPool, LoopsFromTwoThreadsAtOnceBothFinish) {
  std::atomic<long> sum{0};
  const auto loops = [&] {
    for (int loop = 0; loop < 300; ++loop) {
      for_each_with_slot(64, 2, [&](std::size_t k, unsigned) { sum += long(k); });
    }
  };
  std::thread other(loops);
  loops();
  other.join();
  EXPECT_EQ(sum, 2L * 300 * (63 * 64 / 2));
}

TEST(WorkerPool, AThrowingLoopReachesItsCallerAndThePoolGoesOn) {
  EXPECT_THROW(for_each_with_slot(100, 2, [](std::size_t k, unsigned) {
                 if (k == 37) throw std::runtime_error("piece 37");
               }),
               std::runtime_error);
  bool slots_below = false;
  EXPECT_EQ(runs_of(100, 2, slots_below), std::vector<int>(100, 1));
}

// Every piece runs, and the error rethrown is the lowest failing piece's
// whatever the threads and whichever failed first in time.
TEST(WorkerPool, TheLowestFailingPieceIsTheErrorOnAnyNumberOfThreads) {
  for (const unsigned threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> runs(40);
    try {
      for_each_lowest_failure_first(runs.size(), threads, [&](std::size_t k) {
        ++runs[k];
        if (k == 31) throw std::runtime_error("piece 31");
        if (k == 9) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));  // fails after 31 has
          throw std::runtime_error("piece 9");
        }
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "piece 9") << threads << " threads";
    }
    for (const auto& r : runs) EXPECT_EQ(r, 1) << threads << " threads";
  }
}

TEST(WorkerPool, AForkedChildRunsLoopsOnAPoolOfItsOwn) {
  bool slots_below = false;
  ASSERT_EQ(runs_of(10, 2, slots_below), std::vector<int>(10, 1));  // the parent's pool has a thread
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(20);  // the child's copy of the parent's pool has no threads: waiting on it would hang
    bool below = false;
    const bool all_once = runs_of(1000, 2, below) == std::vector<int>(1000, 1);
    _exit(all_once && below ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child was ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace meshparticles::testing
