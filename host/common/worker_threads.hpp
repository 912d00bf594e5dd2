#pragma once
// Threads that are always joined, and that may be fewer than asked for.
// Under an address-space limit (ulimit -v) the system may refuse a thread
// its stack; std::thread then throws, and a std::thread left joinable on the
// way out ends the program (std::terminate). Here a refused thread ends the
// starting, the caller does the shares that did not start, and every thread
// that did start is joined however the scope ends.
#include <algorithm>
#include <functional>
#include <system_error>
#include <thread>
#include <vector>

namespace meshparticles {

// `threads`, or every core where it is 0 (what --threads 0 asks for).
inline unsigned cores_or(unsigned threads) { return threads ? threads : std::max(1u, std::thread::hardware_concurrency()); }

class WorkerThreads {
 public:
  // Starts work(0), ..., work(count - 1), each on its own thread, until the
  // system refuses one.
  WorkerThreads(unsigned count, const std::function<void(unsigned)>& work) {
    for (unsigned index = 0; index < count; ++index) {
      try {
        threads_.emplace_back(work, index);
      } catch (const std::system_error&) {
        break;
      }
    }
  }
  ~WorkerThreads() { join(); }
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;

  // How many started: work(started()) onwards did not.
  unsigned started() const { return unsigned(threads_.size()); }

  void join() {
    for (std::thread& thread : threads_) {
      if (thread.joinable()) thread.join();
    }
  }

 private:
  std::vector<std::thread> threads_;
};

}  // namespace meshparticles
