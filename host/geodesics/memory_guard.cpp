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

}  // namespace

std::string gibibytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f GiB", bytes / double(1ull << 30));
  return text;
}

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

std::uint64_t usable_host_memory_bytes() {
  return std::uint64_t(kUsableFraction * double(available_host_memory_bytes()));
}

std::uint64_t max_vertices_for(std::uint64_t bytes, std::uint64_t bytes_per_entry) {
  return std::uint64_t(std::sqrt(double(bytes) / double(bytes_per_entry)));
}

void check_table_fits(std::uint64_t vertex_count, std::uint64_t bytes_per_entry, std::uint64_t usable_bytes,
                      const std::string& what, const std::string& where) {
  const double needed = double(vertex_count) * double(vertex_count) * double(bytes_per_entry);
  if (needed <= double(usable_bytes)) return;
  throw UserError("the " + std::to_string(vertex_count) + " x " + std::to_string(vertex_count) + " " + what +
                  " needs " + gibibytes(needed) + " but " + where + " holds " + gibibytes(double(usable_bytes)) +
                  ": at most " + std::to_string(max_vertices_for(usable_bytes, bytes_per_entry)) + " vertices fit");
}

}  // namespace meshparticles
