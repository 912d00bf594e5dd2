#pragma once
// summary.csv and summary.json of a batch: one row per mesh, in the order of
// the inputs whatever order the meshes were done in, so that two batches of
// the same inputs (one process or many) write the same rows.
//
// A row's keys, which are also the CSV's columns in this order:
//   mesh, output          the mesh file as given, its output folder's name
//   status, reason        ok | refused | failed | pending, and the one-line
//                         reason of a refusal or failure
//   vertices, n, distances, iterations, converged, energy
//   nn_min, nn_mean, nn_cv, rho, cover, stacked    the quality metrics
//   seconds_geodesics, seconds_particles, seconds_total
// Only the seconds may differ between two batches of the same inputs.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace meshparticles {

enum class MeshStatus { ok, refused, failed, pending };
std::string mesh_status_name(MeshStatus status);

// The keys whose values are measured times.
inline const std::vector<std::string> kTimingFields = {"seconds_geodesics", "seconds_particles", "seconds_total"};

// A mesh not done (yet).
nlohmann::json pending_row(const std::string& mesh, const std::string& output);
// A mesh done: its figures, read from its report.json.
nlohmann::json finished_row(const std::string& mesh, const std::string& output, const nlohmann::json& report);
// A mesh refused or failed, with the one-line reason.
nlohmann::json problem_row(const std::string& mesh, const std::string& output, MeshStatus status,
                           const std::string& reason);

// The row's status.
MeshStatus row_status(const nlohmann::json& row);

// summary.json ({"timing_fields": [...], "counts": {...}, "meshes": [rows]})
// and summary.csv in `directory`, each replaced atomically.
void write_batch_summary(const std::filesystem::path& directory, const std::vector<nlohmann::json>& rows);

}  // namespace meshparticles
