#include "reports/run_outputs.hpp"

#include <unistd.h>

#include <cstdio>

#include "common/atomic_file.hpp"
#include "common/user_error.hpp"
#include "reports/paraview_export.hpp"

namespace meshparticles {

namespace {

double mean(const std::vector<IterationRecord>& trace, double IterationRecord::*field) {
  double sum = 0;
  for (const auto& record : trace) sum += record.*field;
  return trace.empty() ? 0.0 : sum / double(trace.size());
}

void write_points(std::ostream& out, const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  char line[96];
  for (const VertexId v : positions) {
    const Vec3& p = mesh.positions()[v];
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
    out << line;
  }
}

void write_csv(std::ostream& out, const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  out << "particle,vertex,x,y,z\n";
  char line[128];
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = mesh.positions()[positions[i]];
    std::snprintf(line, sizeof line, "%zu,%u,%.9g,%.9g,%.9g\n", i, unsigned(mesh.input_id(positions[i])), p.x, p.y,
                  p.z);
    out << line;
  }
}

}  // namespace

nlohmann::json run_report(const SurfaceMesh& mesh, const RunContext& context, const RunOutcome& outcome) {
  nlohmann::json trace = nlohmann::json::array();
  bool has_kernel_times = false;
  double kernel_ms_sum = 0;
  for (const auto& record : outcome.trace) {
    nlohmann::json entry = {{"energy", record.energy}, {"moved", record.moved}, {"ms", record.ms}};
    if (record.kernel_ms) {
      entry["kernel_ms"] = *record.kernel_ms;
      kernel_ms_sum += *record.kernel_ms;
      has_kernel_times = true;
    }
    trace.push_back(entry);
  }
  nlohmann::json report = {
      {"mesh", {{"path", context.mesh_path},
                {"vertices", mesh.vertex_count()},
                {"faces", mesh.triangle_count()},
                {"area", mesh.area()}}},
      {"params", context.params},
      {"device", context.device},
      {"iterations_run", outcome.trace.size()},
      {"stopped", outcome.converged ? "converged" : "max_iterations"},
      {"initial_energy", outcome.initial_energy},
      {"final_energy", outcome.trace.empty() ? outcome.initial_energy : outcome.trace.back().energy},
      {"avg_iteration_ms", mean(outcome.trace, &IterationRecord::ms)},
      {"trace", trace}};
  if (has_kernel_times) report["avg_kernel_ms"] = kernel_ms_sum / double(outcome.trace.size());
  return report;
}

void prepare_output_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory)) {
    throw UserError("cannot create output directory " + directory.string() +
                    (error ? ": " + error.message() : ": a file of that name exists"));
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    throw UserError("cannot write to output directory " + directory.string() + ": permission denied");
  }
}

void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh,
                       const std::vector<VertexId>& positions, const nlohmann::json& report,
                       std::span<const float> distance_to_nearest_particle) {
  write_file_atomically(directory / "particles.particles", [&](std::ostream& out) { write_points(out, mesh, positions); });
  write_file_atomically(directory / "particles.csv", [&](std::ostream& out) { write_csv(out, mesh, positions); });
  write_particles_ply(directory / "particles.ply", mesh, positions);
  write_mesh_field_vtk(directory / "mesh_distance.vtk", mesh, distance_to_nearest_particle,
                       "distance_to_nearest_particle");
  write_file_atomically(directory / "report.json", [&](std::ostream& out) { out << report.dump(2) << "\n"; });
}

}  // namespace meshparticles
