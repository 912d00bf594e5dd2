#pragma once
// How much more memory this process may take, and what sets that: the
// machine's available memory, or a tighter limit the process runs under
// (clusters run jobs under `ulimit -v` or a cgroup's memory.max). Every
// place that judges memory asks here, so a limit is never mistaken for
// the machine's 20 GiB.
#include <cstdint>
#include <new>
#include <optional>
#include <string>

#include "common/user_error.hpp"

namespace meshparticles {

// A refusal because something would not fit in memory. The pipeline adds
// the mesh's name (see naming_memory_failures).
class MemoryRefusal : public UserError {
 public:
  using UserError::UserError;
};

struct MemoryRoom {
  std::uint64_t bytes = 0;
  // Names what sets it, for messages: "host memory", "the address-space
  // limit (ulimit -v 800000 KiB)", "the cgroup's memory limit (2.00 GiB)".
  std::string set_by;
};

// The tightest of: MemAvailable; RLIMIT_AS and RLIMIT_DATA less what this
// process already maps; the cgroup's limit less its usage (v1 and v2).
MemoryRoom memory_room();

// The smaller of RLIMIT_AS and RLIMIT_DATA, when either is set.
std::optional<std::uint64_t> address_space_limit_bytes();

// "1.25 GiB".
std::string gibibytes(double bytes);

// What a run's out-of-memory message suggests.
inline constexpr const char* kRunMemoryHint = "fewer particles, a smaller --cutoff or --distances local need less";

// `work()`, with an out-of-memory inside it said where: a MemoryRefusal
// gains "LABEL: ", and std::bad_alloc becomes "LABEL: out of memory while
// STAGE (X left under WHAT SETS IT): HINT". Both become plain UserErrors, so
// an outer stage does not name them twice.
template <class Work>
decltype(auto) naming_memory_failures(const std::string& label, const std::string& stage, Work&& work,
                                      const std::string& hint = kRunMemoryHint) {
  try {
    return work();
  } catch (const MemoryRefusal& refusal) {
    throw UserError(label + ": " + refusal.what(), refusal.exit_code());
  } catch (const std::bad_alloc&) {
    const MemoryRoom room = memory_room();
    throw UserError(label + ": out of memory while " + stage + " (" + gibibytes(double(room.bytes)) + " left under " +
                    room.set_by + "): " + hint);
  }
}

}  // namespace meshparticles
