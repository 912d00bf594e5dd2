#include "geodesics/memory_guard.hpp"

#include <cmath>
#include <cstdio>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// Leave room for everything else the process and the machine need.
constexpr double kUsableFraction = 0.85;

}  // namespace

std::uint64_t usable_host_memory_bytes() { return std::uint64_t(kUsableFraction * double(memory_room().bytes)); }

std::string usable_host_memory_name() {
  const std::string set_by = memory_room().set_by;
  return set_by == "host memory" ? set_by : "the room under " + set_by;
}

std::uint64_t max_vertices_for(std::uint64_t bytes, std::uint64_t bytes_per_entry) {
  return std::uint64_t(std::sqrt(double(bytes) / double(bytes_per_entry)));
}

void check_table_fits(std::uint64_t vertex_count, std::uint64_t bytes_per_entry, std::uint64_t usable_bytes,
                      const std::string& what, const std::string& where, const std::string& hint) {
  const double needed = double(vertex_count) * double(vertex_count) * double(bytes_per_entry);
  if (needed <= double(usable_bytes)) return;
  throw MemoryRefusal("the " + std::to_string(vertex_count) + " x " + std::to_string(vertex_count) + " " + what +
                  " needs " + gibibytes(needed) + " but " + where + " holds " + gibibytes(double(usable_bytes)) +
                  ": at most " + std::to_string(max_vertices_for(usable_bytes, bytes_per_entry)) + " vertices fit" + hint);
}

}  // namespace meshparticles
