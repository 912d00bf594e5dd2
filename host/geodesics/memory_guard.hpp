#pragma once
// Refuses a V x V table that would not fit, before anything is computed or
// allocated: a clear message beats being killed by the out-of-memory killer
// or refused by a device after minutes of work.
#include <cstdint>
#include <string>

namespace meshparticles {

// MemAvailable from /proc/meminfo; a large value where it cannot be read.
std::uint64_t available_host_memory_bytes();

// What of the host's available memory one process may plan to use: room is
// left for everything else the process and the machine need.
std::uint64_t usable_host_memory_bytes();

// The most vertices whose V x V table of `bytes_per_entry` fits in `bytes`.
std::uint64_t max_vertices_for(std::uint64_t bytes, std::uint64_t bytes_per_entry = sizeof(float));

// Throws UserError "the V x V WHAT needs X GiB but WHERE holds Y GiB: at
// most N vertices fit" when V^2 * bytes_per_entry exceeds `usable_bytes`.
void check_table_fits(std::uint64_t vertex_count, std::uint64_t bytes_per_entry, std::uint64_t usable_bytes,
                      const std::string& what, const std::string& where);

// "1.25 GiB".
std::string gibibytes(double bytes);

}  // namespace meshparticles
