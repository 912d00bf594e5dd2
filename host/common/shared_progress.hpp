#pragma once
// A progress line (common/progress) that the threads of a stage advance
// together, a unit each.
#include <cstddef>
#include <mutex>

#include "common/progress.hpp"

namespace meshparticles {

class SharedProgress {
 public:
  SharedProgress(const char* label, std::size_t total, bool quiet) : line_(label, total, quiet) {}
  void advance() {
    const std::lock_guard lock(mutex_);
    line_.update(++done_);
  }
  void finish() { line_.finish(); }

 private:
  std::mutex mutex_;
  ProgressLine line_;
  std::size_t done_ = 0;
};

}  // namespace meshparticles
