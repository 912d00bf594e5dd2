#include "batch/reusable_output.hpp"

#include <algorithm>
#include <fstream>
#include <vector>

#include "reports/batch_summary.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"

namespace meshparticles {

namespace {

std::vector<std::string> lines_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(std::move(line));
  return lines;
}

// The lines after the first one equal to `marker` (all lines when it is empty).
std::size_t rows_after(const std::vector<std::string>& lines, const std::string& marker) {
  if (marker.empty()) return lines.size();
  const auto found = std::find(lines.begin(), lines.end(), marker);
  return found == lines.end() ? 0 : std::size_t(lines.end() - found - 1);
}

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

// `vertices`: of the mesh the particles moved on (spread: the working mesh).
bool rows_match(const std::filesystem::path& directory, std::size_t particles, std::size_t vertices) {
  const auto field = lines_of(directory / "mesh_distance.vtk");
  const auto xml_field = lines_of(directory / "mesh_distance.vtp");
  const std::string xml_points = "NumberOfPoints=\"" + std::to_string(vertices) + "\"";
  const bool xml_matches = std::any_of(xml_field.begin(), xml_field.end(), [&](const std::string& line) {
    return line.find(xml_points) != std::string::npos;
  });
  return xml_matches && xml_field.size() > 1 && xml_field.back() == "</VTKFile>" &&
         rows_after(lines_of(directory / "particles.particles"), "") == particles &&
         rows_after(lines_of(directory / "particles.csv"), kParticlesCsvHeader) == particles &&
         rows_after(lines_of(directory / "particles.ply"), "end_header") == particles &&
         std::count(field.begin(), field.end(), "POINTS " + std::to_string(vertices) + " float") == 1 &&
         rows_after(field, "LOOKUP_TABLE default") == vertices;
}

}  // namespace

std::optional<nlohmann::json> reusable_report(const std::filesystem::path& directory, const SurfaceMesh& mesh,
                                              const RunPlan& plan, const std::string& mesh_sha256) {
  if (!holds_exactly_a_run(directory)) return std::nullopt;
  std::ifstream in(directory / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!report.is_object()) return std::nullopt;
  const nlohmann::json expected_mesh = {{"path", plan.request.mesh_label},
                                        {"sha256", mesh_sha256},
                                        {"vertices", mesh.vertex_count()}};
  const nlohmann::json recorded_mesh = report.value("mesh", nlohmann::json::object());
  for (const auto& [key, value] : expected_mesh.items()) {
    if (recorded_mesh.value(key, nlohmann::json()) != value) return std::nullopt;
  }
  if (without_out(report.value("params", nlohmann::json::object())) != without_out(run_parameters(plan, directory))) {
    return std::nullopt;
  }
  // The store is no parameter of report.json's, but a run on local balls may
  // stop elsewhere than one on the dense table.
  const nlohmann::json distances = report.value("distances", nlohmann::json::object());
  if (distances.value("store", "") != store_kind_name(plan.distances.kind)) return std::nullopt;
  if (plan.distances.kind == StoreKind::local && distances.value("radius", -1.0) != plan.distances.radius) {
    return std::nullopt;
  }
  try {
    // spread: the vertices of the working mesh, as the report says (the
    // plan does not know them).
    const std::size_t vertices = plan.method == Method::spread
                                     ? report.at("working_mesh").at("vertices").get<std::size_t>()
                                     : mesh.vertex_count();
    if (!rows_match(directory, plan.request.particles, vertices)) return std::nullopt;
    finished_row(plan.request.mesh_label, directory.filename().string(), report);  // every figure the summary reads
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  return report;
}

}  // namespace meshparticles
