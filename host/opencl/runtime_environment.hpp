#pragma once
// What must hold before the OpenCL runtime is touched at all: some
// environments make it abort or hang inside its own code, where no error
// can be caught or reported. Each is refused here in one line instead.
#include <cstdint>
#include <optional>
#include <string>

namespace meshparticles {

// Below this address-space limit (ulimit -v) PoCL's kernel build hangs
// (measured: for ever at 640 MiB, 8 s at 768 MiB, with a cold cache) and
// its thread pool aborts under 300 MiB. GPU runtimes reserve far more.
inline constexpr std::uint64_t kOpenClMinimumAddressSpace = std::uint64_t(1) << 30;

// Why the runtime cannot start safely here, or nothing:
// - $POCL_CACHE_DIR set but empty (PoCL aborts on an assertion), not a
//   directory, or not writable (PoCL cannot build kernels);
// - an address-space or data limit under kOpenClMinimumAddressSpace.
std::optional<std::string> runtime_environment_problem();

}  // namespace meshparticles
