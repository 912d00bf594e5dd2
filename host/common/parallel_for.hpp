#pragma once
// Independent pieces of work shared out among threads: work(k) for every k
// in a range or a list, each k on whichever thread takes it next. Each piece must be
// its own work (no piece reads what another writes), so that the result does
// not depend on the number of threads.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "common/worker_pool.hpp"
#include "common/worker_threads.hpp"

namespace meshparticles {

// Runs work(k, slot) for k = 0 .. count - 1 on at most `threads` threads
// (the caller's among them, the others the worker pool's where it is free);
// `slot`, below `threads`, names the thread running it, so that each may
// keep scratch of its own. The first exception stops the others from taking
// more and is rethrown here.
inline void for_each_with_slot(std::size_t count, unsigned threads,
                               const std::function<void(std::size_t, unsigned)>& work) {
  if (count == 0) return;
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex mutex;
  const auto share = [&](unsigned slot) {
    try {
      for (std::size_t k = next++; k < count; k = next++) work(k, slot);
    } catch (...) {  // out of memory, a mesh that cannot be read: rethrown on the calling thread
      const std::lock_guard lock(mutex);
      if (!failure) failure = std::current_exception();
      next = count;
    }
  };
  const unsigned used = unsigned(std::clamp<std::size_t>(threads, 1, count));
  if (used == 1) {
    share(0);
  } else if (!run_on_worker_pool(used - 1, share)) {  // the pool is busy: threads of its own
    WorkerThreads workers(used - 1, [&](unsigned index) { share(index + 1); });
    share(0);
  }
  if (failure) std::rethrow_exception(failure);
}

// How many pieces of `piece_size` indices 0 .. count - 1 is cut into.
inline std::size_t piece_count(std::size_t count, std::size_t piece_size) {
  return (count + piece_size - 1) / piece_size;
}

// Runs work(piece, from, to) for each piece of `piece_size` consecutive
// indices of 0 .. count - 1 (the last may be shorter) on at most `threads`
// threads. The pieces do not depend on the threads: results kept per piece
// and combined in piece order are the same for any number of them.
inline void for_each_piece(std::size_t count, std::size_t piece_size, unsigned threads,
                           const std::function<void(std::size_t, std::size_t, std::size_t)>& work) {
  for_each_with_slot(piece_count(count, piece_size), threads, [&](std::size_t piece, unsigned) {
    work(piece, piece * piece_size, std::min(count, (piece + 1) * piece_size));
  });
}

// Runs work(k) for k = 0 .. count - 1 as for_each_with_slot does, but each
// piece runs even where another throws, and the exception rethrown is the
// lowest k's: the same error for any number of threads (of files written
// side by side on a full disk, the first file's).
inline void for_each_lowest_failure_first(std::size_t count, unsigned threads,
                                          const std::function<void(std::size_t)>& work) {
  std::vector<std::exception_ptr> failures(count);
  for_each_with_slot(count, threads, [&](std::size_t k, unsigned) {
    try {
      work(k);
    } catch (...) {
      failures[k] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

// Runs work(k) for every k of `indices` as for_each_with_slot does.
inline void for_each_index(const std::vector<std::size_t>& indices, unsigned threads,
                           const std::function<void(std::size_t)>& work) {
  for_each_with_slot(indices.size(), threads, [&](std::size_t i, unsigned) { work(indices[i]); });
}

}  // namespace meshparticles
