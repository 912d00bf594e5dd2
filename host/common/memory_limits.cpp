#include "common/memory_limits.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace meshparticles {

namespace {

constexpr std::uint64_t kUnknown = std::numeric_limits<std::uint64_t>::max();

// "KEY: N kB" from a /proc file, in bytes.
std::uint64_t proc_kibibytes(const char* file, const std::string& wanted) {
  std::ifstream in(file);
  std::string key, unit;
  std::uint64_t kibibytes = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    if (fields >> key >> kibibytes && key == wanted) return kibibytes * 1024;
  }
  return kUnknown;
}

// One number from a cgroup file; "max" and unreadable files are no limit.
std::uint64_t cgroup_number(const std::string& file) {
  std::ifstream in(file);
  std::uint64_t value = 0;
  return in >> value ? value : kUnknown;
}

// The cgroup's limit less its usage, v2 ("0::/path") or v1 ("N:memory:/path");
// the path may not be visible inside a container, then the mount's root.
std::uint64_t cgroup_room() {
  std::ifstream in("/proc/self/cgroup");
  std::uint64_t room = kUnknown;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find(':');
    const auto second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    std::string base, limit_file, usage_file;
    if (controllers.empty()) {
      base = "/sys/fs/cgroup", limit_file = "memory.max", usage_file = "memory.current";
    } else if (controllers == "memory") {
      base = "/sys/fs/cgroup/memory", limit_file = "memory.limit_in_bytes", usage_file = "memory.usage_in_bytes";
    } else {
      continue;
    }
    for (const std::string& directory : {base + path, base}) {
      const std::uint64_t limit = cgroup_number(directory + "/" + limit_file);
      if (limit == kUnknown) continue;
      const std::uint64_t usage = cgroup_number(directory + "/" + usage_file);
      room = std::min(room, usage == kUnknown ? limit : usage >= limit ? 0 : limit - usage);
      break;
    }
  }
  return room;
}

std::uint64_t soft_limit(int resource) {
  struct rlimit limit {};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnknown;
  return std::uint64_t(limit.rlim_cur);
}

std::string kibibytes_text(std::uint64_t bytes) { return std::to_string(bytes / 1024) + " KiB"; }

}  // namespace

std::string gibibytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f GiB", bytes / double(1ull << 30));
  return text;
}

std::optional<std::uint64_t> address_space_limit_bytes() {
  const std::uint64_t limit = std::min(soft_limit(RLIMIT_AS), soft_limit(RLIMIT_DATA));
  if (limit == kUnknown) return std::nullopt;
  return limit;
}

MemoryRoom memory_room() {
  MemoryRoom room{proc_kibibytes("/proc/meminfo", "MemAvailable:"), "host memory"};
  const auto consider = [&](std::uint64_t limit, std::uint64_t used, const std::string& name) {
    if (limit == kUnknown) return;
    const std::uint64_t left = used == kUnknown || used >= limit ? 0 : limit - used;
    if (left < room.bytes) room = {left, name};
  };
  // Limits count what is mapped already (the binary, libraries, an OpenCL
  // runtime's reservations), not only what is resident.
  const std::uint64_t address_space = soft_limit(RLIMIT_AS);
  consider(address_space, proc_kibibytes("/proc/self/status", "VmSize:"),
           "the address-space limit (ulimit -v " + kibibytes_text(address_space) + ")");
  const std::uint64_t data = soft_limit(RLIMIT_DATA);
  consider(data, proc_kibibytes("/proc/self/status", "VmData:"),
           "the data-segment limit (ulimit -d " + kibibytes_text(data) + ")");
  const std::uint64_t cgroup = cgroup_room();
  if (cgroup < room.bytes) room = {cgroup, "the cgroup's memory limit (" + gibibytes(double(cgroup)) + " left)"};
  return room;
}

}  // namespace meshparticles
