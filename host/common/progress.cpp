#include "common/progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "common/interruption.hpp"

namespace meshparticles {

ProgressLine::ProgressLine(std::string label, std::size_t total, bool quiet, double shown_after)
    : label_(std::move(label)),
      total_(total),
      done_(total),
      quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) != 0),
      shown_after_(shown_after),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double ProgressLine::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressLine::update(std::size_t done, const std::string& detail) {
  throw_if_interrupted();
  done_ = done;
  if (quiet_ || !terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(200) && done < total_) return;
  const double elapsed = elapsed_seconds();
  if (elapsed < shown_after_) return;
  last_draw_ = now;
  const double eta = done > 0 ? elapsed * double(total_ - done) / double(done) : 0.0;
  std::fprintf(stderr, "\r%s: %zu/%zu  %s%selapsed %.1f s  ETA %.1f s   ", label_.c_str(), done, total_,
               detail.c_str(), detail.empty() ? "" : "  ", elapsed, eta);
  std::fflush(stderr);
}

void ProgressLine::finish(const std::string& suffix) {
  if (quiet_ || elapsed_seconds() < shown_after_) return;  // nothing was drawn
  if (terminal_) std::fputs("\r\033[K", stderr);
  std::fprintf(stderr, "%s: %zu done in %.2f s%s%s\n", label_.c_str(), done_, elapsed_seconds(),
               suffix.empty() ? "" : ", ", suffix.c_str());
}

}  // namespace meshparticles
