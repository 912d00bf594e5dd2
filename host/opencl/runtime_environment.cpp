#include "opencl/runtime_environment.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "common/memory_limits.hpp"

namespace meshparticles {

namespace {

std::optional<std::string> pocl_cache_problem() {
  const char* value = std::getenv("POCL_CACHE_DIR");
  if (!value) return std::nullopt;
  const std::string hint = ": unset it or point it at a directory of yours";
  if (!*value) return "$POCL_CACHE_DIR is set but empty, and PoCL aborts on it" + hint;
  const std::string named = std::string("$POCL_CACHE_DIR='") + value + "'";
  // PoCL would make a missing directory: make it now, to learn whether it can.
  std::error_code error;
  std::filesystem::create_directories(value, error);
  struct stat status {};
  if (::stat(value, &status) != 0) {
    return named + " cannot be made (" + (error ? error.message() : std::string(std::strerror(errno))) +
           "), and PoCL cannot build kernels without its cache" + hint;
  }
  if (!S_ISDIR(status.st_mode)) {
    return named + " is not a directory, and PoCL cannot build kernels without its cache" + hint;
  }
  if (::access(value, W_OK | X_OK) != 0) {
    return named + " is not writable (" + std::string(std::strerror(errno)) +
           "), and PoCL cannot build kernels without its cache" + hint;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> runtime_environment_problem() {
  if (auto problem = pocl_cache_problem()) return problem;
  if (const auto limit = address_space_limit_bytes(); limit && *limit < kOpenClMinimumAddressSpace) {
    return "the process's address-space or data limit (ulimit -v / -d: " + std::to_string(*limit / 1024) +
           " KiB) is under the " + std::to_string(kOpenClMinimumAddressSpace >> 20) +
           " MiB an OpenCL runtime needs to build kernels (below it PoCL hangs): raise the limit, or use "
           "--backend serial-field, which needs no OpenCL";
  }
  return std::nullopt;
}

}  // namespace meshparticles
