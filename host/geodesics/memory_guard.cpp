#include "geodesics/memory_guard.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// Leave room for everything else the process and the machine need.
constexpr double kUsableFraction = 0.85;

std::string gibibytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f GiB", bytes / double(1ull << 30));
  return text;
}

}  // namespace

std::uint64_t available_host_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kibibytes = 0;
  std::string unit;
  while (meminfo >> key >> kibibytes >> unit) {
    if (key == "MemAvailable:") return kibibytes * 1024;
  }
  return std::numeric_limits<std::uint64_t>::max();
}

std::uint64_t max_vertices_for(std::uint64_t bytes) {
  return std::uint64_t(std::sqrt(double(bytes) / sizeof(float)));
}

void check_distance_table_fits(std::uint64_t vertex_count, std::uint64_t available_bytes, const std::string& where) {
  const double needed = double(vertex_count) * double(vertex_count) * sizeof(float);
  const double usable = kUsableFraction * double(available_bytes);
  if (needed <= usable) return;
  throw UserError("the " + std::to_string(vertex_count) + " x " + std::to_string(vertex_count) +
                  " distance table needs " + gibibytes(needed) + " but " + where + " allows " + gibibytes(usable) +
                  ": at most " + std::to_string(max_vertices_for(std::uint64_t(usable))) + " vertices fit");
}

}  // namespace meshparticles
