#include "batch/reusable_output.hpp"

#include "common/json_text.hpp"
#include "common/version.hpp"
#include "reports/batch_summary.hpp"
#include "reports/output_digests.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"

namespace meshparticles {

namespace {

bool holds_exactly_a_run(const std::filesystem::path& directory) {
  std::error_code error;
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    if (!entry.is_regular_file(error) || !kRunOutputFiles.count(entry.path().filename().string())) return false;
    ++files;
  }
  return !error && files == kRunOutputFiles.size();
}

nlohmann::json without_out(nlohmann::json params) {
  params.erase("out");
  return params;
}

}  // namespace

std::optional<nlohmann::json> reusable_report(const std::filesystem::path& directory, const SurfaceMesh& mesh,
                                              const RunPlan& plan, const std::string& mesh_sha256) {
  if (!holds_exactly_a_run(directory)) return std::nullopt;
  const std::optional<nlohmann::json> intact = intact_report(directory / "report.json");
  if (!intact) return std::nullopt;
  const nlohmann::json& report = *intact;
  try {  // a value of another type than a run writes (a forged report) throws: not reusable
    // Another version may place other particles from the same inputs: a
    // population is never a mix of two versions' runs.
    if (report.value("version", "") != program_version()) return std::nullopt;
    // As written: a path that is not UTF-8 is recorded escaped (common/json_text.hpp).
    const nlohmann::json expected_mesh = as_written({{"path", plan.request.mesh_label},
                                                     {"sha256", mesh_sha256},
                                                     {"vertices", mesh.vertex_count()}});
    const nlohmann::json recorded_mesh = report.value("mesh", nlohmann::json::object());
    for (const auto& [key, value] : expected_mesh.items()) {
      if (recorded_mesh.value(key, nlohmann::json()) != value) return std::nullopt;
    }
    const nlohmann::json expected_params = as_written(without_out(run_parameters(plan, directory)));
    if (without_out(report.value("params", nlohmann::json::object())) != expected_params) {
      return std::nullopt;
    }
    // The store is no parameter of report.json's, but a run on local balls may
    // stop elsewhere than one on the dense table.
    const nlohmann::json distances = report.value("distances", nlohmann::json::object());
    if (distances.value("store", "") != store_kind_name(plan.distances.kind)) return std::nullopt;
    if (plan.distances.kind == StoreKind::local && distances.value("radius", -1.0) != plan.distances.radius) {
      return std::nullopt;
    }
    // Last: it reads every byte of the other files.
    if (!outputs_as_recorded(directory, report)) return std::nullopt;
    finished_row(plan.request.mesh_label, directory.filename().string(), report);  // every figure the summary reads
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  return report;
}

}  // namespace meshparticles
