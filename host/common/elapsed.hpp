#pragma once
// Wall time since a moment, for the seconds the reports give.
#include <chrono>

namespace meshparticles {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace meshparticles
