#include "correspondence/correspondence_checkpoint.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>

#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"
#include "reports/file_digest.hpp"

namespace meshparticles {

namespace {

constexpr const char* kRequestEntry = "request";
constexpr const char* kExtension = ".json";

std::filesystem::path entry_file(const std::filesystem::path& folder, const std::string& name) {
  return folder / (name + kExtension);
}

// An entry file's values, or why they cannot be taken: a header line that
// names `name` and `request` and gives the size and SHA-256 of the values'
// line, then that line.
struct EntryCheck {
  std::optional<nlohmann::json> values;
  std::string problem;
};

constexpr const char* kOtherRequest = "its header names another request";

EntryCheck check_entry(const std::filesystem::path& file, const std::string& name, const std::string& request) {
  // Not followed: an entry is a file we wrote, never a link, a folder or a FIFO.
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::symlink_status(file, error);
  if (!std::filesystem::exists(status)) return {std::nullopt, "it is missing"};
  if (!std::filesystem::is_regular_file(status)) return {std::nullopt, "it is not a file"};
  std::ifstream in(file, std::ios::binary);
  if (!in) return {std::nullopt, "it cannot be read"};
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) return {std::nullopt, "it has no header line"};
  const nlohmann::json header = nlohmann::json::parse(text.substr(0, header_end), nullptr, false);
  const auto field = [&](const char* key) {
    return header.is_object() ? header.value(key, nlohmann::json()) : nlohmann::json();
  };
  if (field("entry") != name) return {std::nullopt, "its header does not name it " + name};
  if (field("request") != request) return {std::nullopt, kOtherRequest};
  const std::string values_line = text.substr(header_end + 1);
  if (values_line.empty() || values_line.back() != '\n' || values_line.find('\n') != values_line.size() - 1) {
    return {std::nullopt, "it is not two whole lines"};
  }
  const std::string values_text = values_line.substr(0, values_line.size() - 1);
  if (field("bytes") != values_text.size()) return {std::nullopt, "its values are not the size its header gives"};
  if (field("sha256") != text_sha256(values_text)) return {std::nullopt, "its values do not match their SHA-256"};
  nlohmann::json values = nlohmann::json::parse(values_text, nullptr, false);
  if (values.is_discarded()) return {std::nullopt, "its values are not JSON"};
  return {std::move(values), ""};
}

// The first entry under `folder` that cannot be taken, as "transfer/002.json:
// why"; empty when all can. Temporaries a killed write left (hidden names)
// are not entries: the next write into their folder removes them, and the
// folder goes with the outputs.
std::string first_damaged_entry(const std::filesystem::path& folder, const std::string& request) {
  std::error_code error;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    const std::filesystem::path relative = it->path().lexically_relative(folder);
    if (it->path().filename().string().starts_with(".")) continue;
    std::string name = relative.generic_string();
    // A stage's folder of shapes; one named like an entry is no entry, and is not read.
    if (it->is_directory(error) && !it->is_symlink(error) && !name.ends_with(kExtension)) continue;
    if (!name.ends_with(kExtension)) return name + ": it is not a checkpoint entry";
    name.resize(name.size() - std::string(kExtension).size());
    const EntryCheck check = check_entry(it->path(), name, request);
    if (!check.values) return relative.generic_string() + ": " + check.problem;
  }
  if (error) return "the folder cannot be read: " + error.message();
  return "";
}

}  // namespace

std::string shape_entry(const std::string& stage, std::size_t shape) {
  char name[32];
  std::snprintf(name, sizeof name, "/%03zu", shape);
  return stage + name;
}

CorrespondCheckpoint::CorrespondCheckpoint(const std::filesystem::path& directory, const nlohmann::json& fingerprint,
                                           bool leader, bool quiet)
    : folder_(directory / kFolder), request_digest_(text_sha256(json_text(fingerprint))) {
  if (!leader) return;
  std::error_code error;
  if (!std::filesystem::exists(folder_, error)) {
    write(kRequestEntry, fingerprint);
    return;
  }
  const EntryCheck request = check_entry(entry_file(folder_, kRequestEntry), kRequestEntry, request_digest_);
  std::string why_anew;
  if (!request.values && request.problem != kOtherRequest) {
    why_anew = folder_.string() + " is damaged (" + std::string(kRequestEntry) + kExtension + ": " + request.problem +
               "): removed it";
  } else if (!request.values || *request.values != fingerprint) {
    why_anew = folder_.string() + " is of other inputs or parameters";
  } else if (const std::string damaged = first_damaged_entry(folder_, request_digest_); !damaged.empty()) {
    why_anew = folder_.string() + " is damaged (" + damaged + "): removed it";
  } else {
    if (!quiet) std::cerr << "meshparticles: resuming from " << folder_.string() << "\n";
    return;
  }
  if (!quiet) std::cerr << "meshparticles: " << why_anew << ": starting anew\n";
  std::filesystem::remove_all(folder_, error);
  if (error) throw UserError("cannot clear " + folder_.string() + ": " + error.message());
  write(kRequestEntry, fingerprint);
}

std::optional<nlohmann::json> CorrespondCheckpoint::read_values(const std::string& name) const {
  if (removed_) return std::nullopt;
  const std::filesystem::path file = entry_file(folder_, name);
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  EntryCheck check = check_entry(file, name, request_digest_);
  if (!check.values) refuse(name, check.problem);
  return std::move(check.values);
}

void CorrespondCheckpoint::refuse(const std::string& name, const std::string& why) const {
  {
    const std::lock_guard lock(writing_);
    removed_ = true;
    std::error_code error;
    std::filesystem::remove_all(folder_, error);
  }
  throw UserError(entry_file(folder_, name).string() + " is damaged (" + why + "): removed " + folder_.string() +
                  "; run the command again to start anew");
}

void CorrespondCheckpoint::write(const std::string& name, const nlohmann::json& values) const {
  const std::lock_guard lock(writing_);
  if (removed_) return;
  const std::filesystem::path file = entry_file(folder_, name);
  create_directory_for(file.parent_path(), "checkpoint folder");
  const std::string values_text = json_text(values);
  const nlohmann::json header = {{"entry", name},
                                 {"request", request_digest_},
                                 {"bytes", values_text.size()},
                                 {"sha256", text_sha256(values_text)}};
  write_file_atomically(file, [&](std::ostream& out) { out << json_text(header) << "\n" << values_text << "\n"; });
}

}  // namespace meshparticles
