#pragma once
// Independent pieces of work shared out among threads: work(k) for every k
// in a list, each k on whichever thread takes it next. Each piece must be
// its own work (no piece reads what another writes), so that the result does
// not depend on the number of threads.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "common/worker_threads.hpp"

namespace meshparticles {

// Runs work(k) for every k of `indices` on at most `threads` threads (the
// caller's among them). The first exception stops the others from taking
// more and is rethrown here.
inline void for_each_index(const std::vector<std::size_t>& indices, unsigned threads,
                           const std::function<void(std::size_t)>& work) {
  if (indices.empty()) return;
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex mutex;
  const std::size_t count = indices.size();
  const auto share = [&] {
    try {
      for (std::size_t i = next++; i < count; i = next++) work(indices[i]);
    } catch (...) {  // out of memory, a mesh that cannot be read: rethrown on the calling thread
      const std::lock_guard lock(mutex);
      if (!failure) failure = std::current_exception();
      next = count;
    }
  };
  const unsigned used = unsigned(std::clamp<std::size_t>(threads, 1, count));
  {
    WorkerThreads workers(used - 1, [&](unsigned) { share(); });
    share();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace meshparticles
