#include "common/temporary_names.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <regex>

namespace meshparticles {

namespace {

// The host name with anything but letters and digits as '_': no dots or
// dashes, so names parse back unambiguously.
const std::string& host_tag() {
  static const std::string tag = [] {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return std::string("host");
    std::string text = name;
    for (char& c : text) {
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return text;
  }();
  return tag;
}

bool process_is_gone(long pid) { return pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

std::filesystem::path temporary_sibling(const std::filesystem::path& destination, TemporaryKind kind) {
  static std::atomic<unsigned> counter{0};
  const bool is_file = kind == TemporaryKind::staging && destination.has_extension();
  std::string name = ".";
  name += is_file ? destination.stem().string() : destination.filename().string();
  name += kind == TemporaryKind::staging ? ".tmp-" : ".old-";
  name += host_tag();
  name += '-';
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  if (is_file) name += destination.extension().string();
  return destination.parent_path() / name;
}

void remove_stale_temporaries(const std::filesystem::path& directory, Writers writers,
                              const std::string& destination) {
  // .NAME.(tmp|old)-HOST-PID-N[.EXT]
  static const std::regex pattern(R"(\.(.+)\.(tmp|old)-([A-Za-z0-9_]+)-([0-9]{1,9})-[0-9]+(\.[^.]*)?)");
  std::error_code error;
  std::filesystem::directory_iterator entries(directory.empty() ? "." : directory, error);
  if (error) return;
  for (const auto& entry : entries) {
    const std::string name = entry.path().filename().string();
    std::smatch match;
    if (!std::regex_match(name, match, pattern)) continue;
    // What it was to become: a staging name keeps the extension after its counter.
    const std::string of = match[1].str() + (match[2] == "tmp" ? match[5].str() : "");
    if (!destination.empty() && of != destination) continue;
    if (writers == Writers::anyone && (match[3] != host_tag() || !process_is_gone(std::stol(match[4])))) continue;
    if (match[2] == "old") {
      const std::filesystem::path retired_from = entry.path().parent_path() / match[1].str();
      if (!std::filesystem::exists(std::filesystem::symlink_status(retired_from, error))) {
        std::filesystem::rename(entry.path(), retired_from, error);
        continue;
      }
    }
    std::filesystem::remove_all(entry.path(), error);
  }
}

}  // namespace meshparticles
