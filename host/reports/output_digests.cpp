#include "reports/output_digests.hpp"

#include <vector>

#include "common/input_file.hpp"
#include "common/json_text.hpp"
#include "common/parallel_for.hpp"
#include "common/user_error.hpp"
#include "reports/file_digest.hpp"
#include "reports/run_outputs.hpp"

namespace meshparticles {

namespace {

constexpr const char* kReportFile = "report.json";

// The one way report.json is written, so that its text can be checked too.
std::string report_text(const nlohmann::json& report) { return json_text(report, 2) + "\n"; }

std::optional<std::string> read_bytes(const std::filesystem::path& file) {
  try {
    return read_input_text(file, file.string());
  } catch (const UserError&) {
    return std::nullopt;  // missing, unreadable or not a regular file: not proven
  }
}

}  // namespace

std::string digested_report_text(nlohmann::json report, const std::filesystem::path& directory, unsigned threads) {
  std::vector<std::string> names;
  for (const std::string& name : kRunOutputFiles) {
    if (name != kReportFile) names.push_back(name);
  }
  std::vector<std::string> digests(names.size());
  for_each_lowest_failure_first(names.size(), threads, [&](std::size_t k) {
    digests[k] = file_sha256(directory / names[k]);  // first: it says why a file cannot be read
  });
  nlohmann::json outputs = nlohmann::json::object();
  for (std::size_t k = 0; k < names.size(); ++k) {
    outputs[names[k]] = {{"bytes", std::filesystem::file_size(directory / names[k])}, {"sha256", digests[k]}};
  }
  report["outputs"] = std::move(outputs);
  report["report_sha256"] = text_sha256(report_text(report));
  return report_text(report);
}

std::optional<nlohmann::json> intact_report(const std::filesystem::path& file) {
  const std::optional<std::string> text = read_bytes(file);
  if (!text) return std::nullopt;
  nlohmann::json report = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  try {
    if (!report.is_object() || report_text(report) != *text) return std::nullopt;
    const nlohmann::json recorded = report.value("report_sha256", nlohmann::json());
    nlohmann::json rest = report;
    rest.erase("report_sha256");
    if (!recorded.is_string() || recorded.get<std::string>() != text_sha256(report_text(rest))) return std::nullopt;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a string dump() refuses (not UTF-8) was not written by a run
  }
  return report;
}

bool outputs_as_recorded(const std::filesystem::path& directory, const nlohmann::json& report) {
  const auto outputs = report.find("outputs");
  if (outputs == report.end() || !outputs->is_object() || outputs->size() + 1 != kRunOutputFiles.size()) return false;
  for (const auto& [name, recorded] : outputs->items()) {
    if (name == kReportFile || !kRunOutputFiles.count(name) || !recorded.is_object()) return false;
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(directory / name, error);
    if (error || recorded.value("bytes", nlohmann::json()) != bytes) return false;
  }
  try {
    for (const auto& [name, recorded] : outputs->items()) {
      if (recorded.value("sha256", nlohmann::json()) != file_sha256(directory / name)) return false;
    }
  } catch (const UserError&) {
    return false;  // unreadable: not proven
  }
  return true;
}

}  // namespace meshparticles
