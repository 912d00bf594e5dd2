#include "reports/quality_bench_report.hpp"

#include <cstdio>

#include "common/text_format.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

std::string cell(const std::optional<double>& value, const char* pattern) {
  return value ? format_number(pattern, *value) : "-";
}

}  // namespace

std::string quality_tables(const std::vector<QualityCase>& cases) {
  std::string text =
      "bench --quality: geodesic metrics of each placement; default = farthest start, monotone K=" +
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
