#pragma once
// Refuses a V x V table that would not fit, before anything is computed or
// allocated: a clear message beats being killed by the out-of-memory killer
// or refused by a device after minutes of work.
#include <cstdint>
#include <string>

#include "common/memory_limits.hpp"

namespace meshparticles {

// What one process may plan to use of the memory it may still take
// (common/memory_limits: the machine's, or a tighter limit): room is left
// for everything else the process and the machine need.
std::uint64_t usable_host_memory_bytes();
// What sets it, for messages ("host memory", "the address-space limit ...").
std::string usable_host_memory_name();

// The most vertices whose V x V table of `bytes_per_entry` fits in `bytes`.
std::uint64_t max_vertices_for(std::uint64_t bytes, std::uint64_t bytes_per_entry = sizeof(float));

// Throws MemoryRefusal "the V x V WHAT needs X GiB but WHERE holds Y GiB:
// at most N vertices fitHINT" when V^2 * bytes_per_entry exceeds
// `usable_bytes`. `hint` names the options that would need less.
void check_table_fits(std::uint64_t vertex_count, std::uint64_t bytes_per_entry, std::uint64_t usable_bytes,
                      const std::string& what, const std::string& where, const std::string& hint = "");


}  // namespace meshparticles
