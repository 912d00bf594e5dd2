#pragma once
// A progress line on stderr for long work: redrawn in place on a terminal
// (at most a few times a second), a single final summary when stderr is a file
// or a pipe, and nothing at all when quiet.
#include <chrono>
#include <cstddef>
#include <string>

namespace meshparticles {

class ProgressLine {
 public:
  // With `shown_after` seconds, nothing is shown (neither the line nor the
  // summary) unless the work lasts that long: for work usually too quick
  // to report that now and then is not.
  ProgressLine(std::string label, std::size_t total, bool quiet, double shown_after = 0);
  // Reports that `done` of `total` units are finished; thread-compatible when
  // called from one thread at a time. Throws Interrupted when the process's
  // interruption check says stop (common/interruption.hpp).
  // `detail` (e.g. "moved 12, energy 623.4") follows the counts.
  void update(std::size_t done, const std::string& detail = "");
  // Prints the final summary (or clears the line on a terminal) with `suffix`.
  void finish(const std::string& suffix = "");
  double elapsed_seconds() const;

 private:
  std::string label_;
  std::size_t total_;
  std::size_t done_;  // the last count reported (work may end early)
  bool quiet_;
  bool terminal_;
  double shown_after_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace meshparticles
