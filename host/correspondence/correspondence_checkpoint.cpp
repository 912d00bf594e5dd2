#include "correspondence/correspondence_checkpoint.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>

#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

constexpr const char* kRequestEntry = "request";

std::filesystem::path entry_file(const std::filesystem::path& folder, const std::string& name) {
  return folder / (name + ".json");
}

std::optional<nlohmann::json> read_entry(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  // A file that does not parse was not written by a finished write: as if absent.
  nlohmann::json value = nlohmann::json::parse(in, nullptr, false);
  if (value.is_discarded()) return std::nullopt;
  return value;
}

}  // namespace

std::string shape_entry(const std::string& stage, std::size_t shape) {
  char name[32];
  std::snprintf(name, sizeof name, "/%03zu", shape);
  return stage + name;
}

CorrespondCheckpoint::CorrespondCheckpoint(const std::filesystem::path& directory, nlohmann::json fingerprint,
                                           bool leader, bool quiet)
    : folder_(directory / kFolder) {
  if (!leader) return;
  const std::optional<nlohmann::json> earlier = read_entry(entry_file(folder_, kRequestEntry));
  std::error_code error;
  if (earlier && *earlier == fingerprint) {
    if (!quiet) std::cerr << "meshparticles: resuming from " << folder_.string() << "\n";
    return;
  }
  if (std::filesystem::exists(folder_, error)) {
    if (!quiet) {
      std::cerr << "meshparticles: " << folder_.string()
                << " is of other inputs or parameters: starting anew\n";
    }
    std::filesystem::remove_all(folder_, error);
    if (error) throw UserError("cannot clear " + folder_.string() + ": " + error.message());
  }
  write(kRequestEntry, fingerprint);
}

std::optional<nlohmann::json> CorrespondCheckpoint::read(const std::string& name) const {
  return read_entry(entry_file(folder_, name));
}

void CorrespondCheckpoint::write(const std::string& name, const nlohmann::json& value) const {
  const std::filesystem::path file = entry_file(folder_, name);
  create_directory_for(file.parent_path(), "checkpoint folder");
  write_file_atomically(file, [&](std::ostream& out) { out << json_text(value) << "\n"; });
}

void CorrespondCheckpoint::remove() const {
  std::error_code error;
  std::filesystem::remove_all(folder_, error);  // what is left is harmless: the next run of these inputs reuses it
}

}  // namespace meshparticles
