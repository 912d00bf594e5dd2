#include "reports/output_digests.hpp"

#include "reports/file_digest.hpp"
#include "reports/run_outputs.hpp"

namespace meshparticles {

namespace {

constexpr const char* kReportFile = "report.json";

// The one way report.json is written, so that its text can be checked too.
std::string report_text(const nlohmann::json& report) { return report.dump(2) + "\n"; }

}  // namespace

std::string digested_report_text(nlohmann::json report, const std::filesystem::path& directory) {
  nlohmann::json outputs = nlohmann::json::object();
  for (const std::string& name : kRunOutputFiles) {
    if (name == kReportFile) continue;
    const std::string sha256 = file_sha256(directory / name);  // first: it says why a file cannot be read
    outputs[name] = {{"bytes", std::filesystem::file_size(directory / name)}, {"sha256", sha256}};
  }
  report["outputs"] = std::move(outputs);
  report["report_sha256"] = text_sha256(report_text(report));
  return report_text(report);
}

}  // namespace meshparticles
