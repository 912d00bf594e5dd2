#pragma once
// Summaries of repeated timings. The machines are noisy, so sweeps and
// benches report the median (typical) and the minimum (least disturbed).
#include <algorithm>
#include <vector>

#include "common/median.hpp"

namespace meshparticles {

struct TimingSummary {
  double median_ms = 0;
  double min_ms = 0;
};

inline TimingSummary summarize_timings(const std::vector<double>& samples) {
  if (samples.empty()) return {};
  return {median(samples), *std::min_element(samples.begin(), samples.end())};
}

}  // namespace meshparticles
