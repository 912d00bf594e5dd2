#pragma once
// Summaries of repeated timings. The machines are noisy, so sweeps and
// benches report the median (typical) and the minimum (least disturbed).
#include <algorithm>
#include <vector>

namespace meshparticles {

struct TimingSummary {
  double median_ms = 0;
  double min_ms = 0;
};

inline TimingSummary summarize_timings(std::vector<double> samples) {
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  const std::size_t middle = samples.size() / 2;
  const double median = samples.size() % 2 ? samples[middle] : (samples[middle - 1] + samples[middle]) / 2;
  return {median, samples.front()};
}

}  // namespace meshparticles
