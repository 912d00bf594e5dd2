#include "reports/batch_summary.hpp"

#include <array>
#include <map>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/text_format.hpp"
#include "common/version.hpp"

namespace meshparticles {

namespace {

constexpr std::array<MeshStatus, 4> kStatuses = {MeshStatus::ok, MeshStatus::refused, MeshStatus::failed,
                                                 MeshStatus::pending};

const std::vector<std::string> kColumns = {
    "mesh",   "output", "status",  "reason", "vertices", "n",       "distances",         "iterations",
    "converged", "energy", "nn_min", "nn_mean", "nn_cv",  "rho",     "cover",             "stacked",
    "seconds_geodesics", "seconds_particles", "seconds_total"};

// Every column, null where the mesh has no value.
nlohmann::json empty_row(const std::string& mesh, const std::string& output, MeshStatus status) {
  nlohmann::json row;
  for (const std::string& column : kColumns) row[column] = nullptr;
  row["mesh"] = mesh;
  row["output"] = output;
  row["status"] = mesh_status_name(status);
  return row;
}

std::string csv_cell(const nlohmann::json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return csv_field(value.get<std::string>());
  return value.dump();
}

}  // namespace

std::string mesh_status_name(MeshStatus status) {
  switch (status) {
    case MeshStatus::ok: return "ok";
    case MeshStatus::refused: return "refused";
    case MeshStatus::failed: return "failed";
    case MeshStatus::pending: return "pending";
  }
  return "pending";
}

MeshStatus row_status(const nlohmann::json& row) {
  for (const MeshStatus status : kStatuses) {
    if (row.at("status") == mesh_status_name(status)) return status;
  }
  throw std::logic_error("summary row with an unknown status: " + row.at("status").dump());
}

nlohmann::json pending_row(const std::string& mesh, const std::string& output) {
  return empty_row(mesh, output, MeshStatus::pending);
}

nlohmann::json finished_row(const std::string& mesh, const std::string& output, const nlohmann::json& report) {
  nlohmann::json row = empty_row(mesh, output, MeshStatus::ok);
  row["vertices"] = report.at("mesh").at("vertices");
  row["n"] = report.at("params").at("n");
  row["distances"] = report.at("distances").at("store");
  row["iterations"] = report.at("iterations_run");
  row["converged"] = report.at("stopped") == "converged";
  row["energy"] = report.at("final_energy");
  const nlohmann::json& quality = report.at("quality");
  for (const char* key : {"nn_min", "nn_mean", "nn_cv", "rho", "cover", "stacked"}) row[key] = quality.at(key);
  const nlohmann::json& seconds = report.at("seconds");
  row["seconds_geodesics"] = seconds.at("geodesics");
  row["seconds_particles"] = seconds.at("particles");
  row["seconds_total"] = seconds.at("total");
  return row;
}

nlohmann::json problem_row(const std::string& mesh, const std::string& output, MeshStatus status,
                           const std::string& reason) {
  nlohmann::json row = empty_row(mesh, output, status);
  row["reason"] = reason;
  return row;
}

void write_batch_summary(const std::filesystem::path& directory, const std::vector<nlohmann::json>& rows) {
  std::map<std::string, std::size_t> counts;
  for (const MeshStatus status : kStatuses) counts[mesh_status_name(status)] = 0;
  for (const nlohmann::json& row : rows) ++counts[row.at("status").get<std::string>()];
  const nlohmann::json summary = {{"version", program_version()}, {"timing_fields", kTimingFields}, {"counts", counts}, {"meshes", rows}};
  write_file_atomically(directory / "summary.json", [&](std::ostream& out) { out << json_text(summary, 2) << "\n"; });
  write_file_atomically(directory / "summary.csv", [&](std::ostream& out) {
    for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << kColumns[c];
    out << "\n";
    for (const nlohmann::json& row : rows) {
      for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << csv_cell(row.at(kColumns[c]));
      out << "\n";
    }
  });
}

}  // namespace meshparticles
