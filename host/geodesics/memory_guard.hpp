#pragma once
// Refuses a distance table that would not fit, before allocating it: a clear
// message beats being killed by the kernel's out-of-memory killer.
#include <cstdint>
#include <string>

namespace meshparticles {

// MemAvailable from /proc/meminfo; a large value where it cannot be read.
std::uint64_t available_host_memory_bytes();

// The most vertices whose V x V float32 table fits in `bytes`.
std::uint64_t max_vertices_for(std::uint64_t bytes);

// Throws UserError naming `where` ("host memory", a device's allocation
// limit), the bytes needed and the vertices that would fit.
void check_distance_table_fits(std::uint64_t vertex_count, std::uint64_t available_bytes, const std::string& where);

}  // namespace meshparticles
