#include "quality/quality_bench.hpp"

#include <cstdio>

#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "reports/text_format.hpp"

namespace meshparticles {

QualityCase quality_case(const std::string& mesh_name, const SurfaceMesh& mesh, const DistanceTable& distances,
                         std::size_t particles, const std::vector<CheckedBackend>& backends,
                         std::size_t max_iterations, const std::function<void(const std::string&)>& on_row) {
  const EnergyParams energy{Potential::exp, default_sigma(Potential::exp, mesh.area(), particles)};
  QualityCase result{mesh_name, mesh.vertex_count(), particles, energy.sigma, {}};
  auto add_start = [&](const std::string& method, Init init) {
    on_row(mesh_name + " n=" + std::to_string(particles) + " " + method);
    const auto start = place_particles(distances, {init, particles, 1, std::nullopt});
    result.rows.push_back({method, "", 0, false, measure_quality(mesh, distances, start, energy), std::nullopt});
  };
  auto add_run = [&](const std::string& method, const CheckedBackend& checked, Init init, Scheme scheme) {
    on_row(mesh_name + " n=" + std::to_string(particles) + " " + method + " on " + checked.name);
    const auto start = place_particles(distances, {init, particles, 1, init == Init::v0 ? std::optional<VertexId>(0)
                                                                                       : std::nullopt});
    const auto backend = make_backend(checked, mesh, distances, energy);
    const RunOutcome outcome = run_particles(*backend, start, {scheme, kDefaultColors, max_iterations, true});
    result.rows.push_back({method, checked.name, outcome.trace.size(), outcome.converged,
                           measure_quality(mesh, distances, outcome.positions, energy), std::nullopt});
  };
  add_start("random", Init::random);
  add_start("farthest", Init::farthest);
  BackendRequest serial;
  serial.name = "serial";
  add_run("paper: v0 + sequential", check_backend(serial, mesh, particles), Init::v0, Scheme::sequential);
  const QualityRow* serial_default = nullptr;
  for (const CheckedBackend& checked : backends) {
    add_run("default", checked, Init::farthest, Scheme::colored);
    if (checked.name == "serial") serial_default = &result.rows.back();
  }
  if (serial_default) {
    const double reference = serial_default->quality.energy;
    for (QualityRow& row : result.rows) {
      if (row.method == "default") row.energy_vs_serial = (row.quality.energy - reference) / reference;
    }
  }
  return result;
}

namespace {

std::string cell(const std::optional<double>& value, const char* pattern) {
  return value ? format_number(pattern, *value) : "-";
}

}  // namespace

std::string quality_tables(const std::vector<QualityCase>& cases) {
  std::string text =
      "bench --quality: geodesic metrics of each placement; default = farthest start, colored K=" +
      std::to_string(kDefaultColors) + " on every backend (serial too), as `run` does; paper = every particle on "
      "vertex 0, then the sequential loop (serial)\n";
  char line[256];
  for (const QualityCase& c : cases) {
    text += "\n" + c.mesh + " (" + std::to_string(c.vertices) + " vertices), n=" + std::to_string(c.particles) +
            ", sigma " + format_number("%.4g", c.sigma) + "\n";
    std::snprintf(line, sizeof line, "%-24s %-12s %6s %10s %8s %8s %8s %8s %8s %14s\n", "placement", "backend",
                  "iters", "energy", "nn_cv", "rho", "cover", "nn_mean", "stacked", "E vs serial");
    text += line;
    for (const QualityRow& row : c.rows) {
      const std::string iterations =
          row.backend.empty() ? "-" : std::to_string(row.iterations) + (row.converged ? "" : "+");
      std::snprintf(line, sizeof line, "%-24s %-12s %6s %10s %8s %8s %8s %8s %8zu %14s\n", row.method.c_str(),
                    row.backend.empty() ? "-" : row.backend.c_str(), iterations.c_str(),
                    format_number("%.2f", row.quality.energy).c_str(), cell(row.quality.nn_cv, "%.4f").c_str(),
                    cell(row.quality.rho, "%.3f").c_str(), cell(row.quality.cover, "%.3f").c_str(),
                    cell(row.quality.nn_mean, "%.4g").c_str(), row.quality.stacked,
                    row.energy_vs_serial ? format_number("%+.4f%%", 100 * *row.energy_vs_serial).c_str() : "-");
      text += line;
    }
  }
  return text + "(iters: + = stopped at the iteration limit, not converged)\n";
}

nlohmann::json quality_bench_json(const std::vector<QualityCase>& cases) {
  nlohmann::json out = nlohmann::json::array();
  for (const QualityCase& c : cases) {
    nlohmann::json rows = nlohmann::json::array();
    for (const QualityRow& row : c.rows) {
      rows.push_back({{"placement", row.method},
                      {"backend", row.backend.empty() ? nlohmann::json(nullptr) : nlohmann::json(row.backend)},
                      {"iterations", row.iterations},
                      {"converged", row.converged},
                      {"quality", quality_json(row.quality)},
                      {"energy_vs_serial", row.energy_vs_serial ? nlohmann::json(*row.energy_vs_serial) : nullptr}});
    }
    out.push_back({{"mesh", c.mesh}, {"vertices", c.vertices}, {"n", c.particles}, {"sigma", c.sigma}, {"rows", rows}});
  }
  return {{"quality_cases", out}};
}

}  // namespace meshparticles
