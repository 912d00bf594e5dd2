#pragma once
// The median of a list of numbers: the middle one once sorted, or the mean
// of the middle two of an even count (0 for none).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace meshparticles {

inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

}  // namespace meshparticles
