#include "reports/bench_report.hpp"

#include <algorithm>
#include <cstdio>

#include "backends/backend_table.hpp"
#include "backends/serial_backend.hpp"
#include "common/atomic_file.hpp"
#include "common/text_format.hpp"
#include "measurement/paper_figures.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

namespace {

std::optional<double> paper_ms(const BenchCase& bench, const std::string& backend) {
  const PaperFigures* figures = paper_figures_for(bench.mesh, bench.particles);
  if (!figures) return std::nullopt;
  switch (find_backend(backend).paper_row) {
    case PaperRow::cpu: return figures->cpu_ms;
    case PaperRow::gpu1_naive: return figures->naive_ms;
    case PaperRow::gpu2_tiled: return figures->tiled_ms;
  }
  return std::nullopt;
}

const BenchRow* row_of(const BenchCase& bench, const std::string& backend) {
  for (const auto& row : bench.rows) {
    if (row.backend == backend) return &row;
  }
  return nullptr;
}

std::optional<double> our_speedup(const BenchCase& bench, const BenchRow& row) {
  const BenchRow* serial = row_of(bench, serial_backend().name);
  if (!serial) return std::nullopt;
  return serial->mean_ms / row.mean_ms;
}

std::optional<double> paper_speedup(const BenchCase& bench, const std::string& backend) {
  const auto cpu = paper_ms(bench, serial_backend().name), ours = paper_ms(bench, backend);
  if (!cpu || !ours) return std::nullopt;
  return *cpu / *ours;
}

std::string speedup_text(std::optional<double> speedup) {
  return speedup ? " [" + format_number(*speedup >= 10 ? "%.0fx" : "%.1fx", *speedup) + "]" : "";
}

// The paper's row a backend is, or for the field methods (not in the paper)
// the one it stands beside: "GPU2", "vs GPU2".
std::string paper_label(const std::string& backend) {
  const BackendDescriptor& descriptor = find_backend(backend);
  const std::string beside = descriptor.field_method ? "vs " : "";
  switch (descriptor.paper_row) {
    case PaperRow::cpu: return beside + "CPU";
    case PaperRow::gpu1_naive: return beside + "GPU1";
    case PaperRow::gpu2_tiled: return beside + "GPU2";
  }
  return "?";
}

// How many times faster than the paper's GPU2 (tiled, GTX 260) a row is.
std::optional<double> versus_paper_gpu2(const BenchCase& bench, const BenchRow& row) {
  const PaperFigures* figures = paper_figures_for(bench.mesh, bench.particles);
  if (!figures || !figures->tiled_ms) return std::nullopt;
  return *figures->tiled_ms / row.mean_ms;
}

// For rows whose work follows the moves: "field: 4.1x the paper's GPU2 at
// n=1024; moved per iteration n=128 12, ..." (one line per backend).
std::string field_lines(const std::vector<const BenchCase*>& columns, const std::vector<std::string>& backends) {
  std::string text;
  for (const std::string& backend : backends) {
    if (!find_backend(backend).field_method) continue;
    std::string versus, moved;
    for (const BenchCase* bench : columns) {
      const BenchRow* row = row_of(*bench, backend);
      if (!row) continue;
      const std::string n = "n=" + std::to_string(bench->particles);
      if (const auto ratio = versus_paper_gpu2(*bench, *row)) {
        versus += (versus.empty() ? "" : ", ") + n + " " + format_number("%.1fx", *ratio);
      }
      moved += (moved.empty() ? "" : ", ") + n + " " + format_number("%.0f", row->moved_mean);
    }
    text += backend + ": particles moved per timed iteration " + moved + "\n";
    if (!versus.empty()) text += backend + ": times faster than the paper's GPU2 " + versus + "\n";
  }
  return text;
}

// The sizes each device row ran with in one table, e.g. "sizes: tiled wg 64
// tile 128 (tuning file)"; several when the particle counts differ.
std::string sizes_line(const std::vector<const BenchCase*>& columns) {
  std::vector<std::string> seen;
  for (const BenchCase* bench : columns) {
    for (const auto& row : bench->rows) {
      const std::string text = row.backend + " " + row.sizes + " (" + row.sizes_from + ")";
      if (!row.sizes.empty() && std::find(seen.begin(), seen.end(), text) == seen.end()) seen.push_back(text);
    }
  }
  std::string line;
  for (const auto& text : seen) line += (line.empty() ? "sizes: " : "; ") + text;
  return line.empty() ? "" : line + "\n";
}

// The rows' backends in the order they were measured.
std::vector<std::string> backends_of(const std::vector<BenchCase>& cases) {
  std::vector<std::string> backends;
  for (const auto& bench : cases) {
    for (const auto& row : bench.rows) {
      if (std::find(backends.begin(), backends.end(), row.backend) == backends.end()) backends.push_back(row.backend);
    }
  }
  return backends;
}

}  // namespace

std::string bench_tables(const std::string& device_name, const BenchSettings& settings,
                         const std::vector<BenchCase>& cases) {
  std::string text = "bench: ms per iteration, mean of " + std::to_string(settings.iterations) +
                     " iterations (the paper: 1000), [speed-up over the serial row of the same table]\n";
  text += "ours: serial = the paper's CPU loop (sequential, 1 thread, double); device rows on " + device_name +
          ", scheme " + scheme_name(settings.device_scheme) +
          (uses_colors(settings.device_scheme) ? " K=" + std::to_string(settings.colors) : "") +
          "; the first iterations from a farthest-point start\n"
          "paper: Xeon CPU and GTX 260 (Tables 1 and 2); field rows stand beside its fastest, GPU2\n";
  std::vector<std::string> meshes;
  for (const auto& bench : cases) {
    if (std::find(meshes.begin(), meshes.end(), bench.mesh) == meshes.end()) meshes.push_back(bench.mesh);
  }
  char cell[96];
  for (const std::string& mesh : meshes) {
    std::vector<const BenchCase*> columns;
    for (const auto& bench : cases) {
      if (bench.mesh == mesh) columns.push_back(&bench);
    }
    text += "\n" + mesh + " (" + std::to_string(columns.front()->vertices) + " vertices)\n";
    std::snprintf(cell, sizeof cell, "%-21s", "particles");
    text += cell;
    for (const BenchCase* bench : columns) {
      std::snprintf(cell, sizeof cell, "  %-17s %-15s", ("n=" + std::to_string(bench->particles) + " ours").c_str(),
                    "paper");
      text += cell;
    }
    text += "\n";
    for (const std::string& backend : backends_of(cases)) {
      std::snprintf(cell, sizeof cell, "%-21s", (backend + " (" + paper_label(backend) + ")").c_str());
      text += cell;
      for (const BenchCase* bench : columns) {
        const BenchRow* row = row_of(*bench, backend);
        const auto paper = paper_ms(*bench, backend);
        const std::string ours = row ? format_number("%.3f", row->mean_ms) + speedup_text(our_speedup(*bench, *row)) : "-";
        const std::string theirs =
            paper ? format_number("%.2f", *paper) + speedup_text(paper_speedup(*bench, backend)) : "-";
        std::snprintf(cell, sizeof cell, "  %-17s %-15s", ours.c_str(), theirs.c_str());
        text += cell;
      }
      text += "\n";
    }
    text += sizes_line(columns);
    text += field_lines(columns, backends_of(cases));
  }
  return text;
}

nlohmann::json bench_json(const std::string& device_name, const BenchSettings& settings,
                          const std::vector<BenchCase>& cases) {
  nlohmann::json out_cases = nlohmann::json::array();
  for (const auto& bench : cases) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : bench.rows) {
      nlohmann::json entry = {{"backend", row.backend},
                              {"scheme", scheme_name(row.scheme)},
                              {"ms_per_iteration", row.mean_ms},
                              {"median_ms", row.timing.median_ms},
                              {"min_ms", row.timing.min_ms},
                              {"speedup_vs_serial", nullptr},
                              {"paper_ms", nullptr},
                              {"paper_speedup", nullptr}};
      if (row.kernel_ms) entry["kernel_ms"] = *row.kernel_ms;
      entry["moved_per_iteration"] = row.moved_mean;
      if (const auto ratio = versus_paper_gpu2(bench, row)) entry["times_faster_than_paper_gpu2"] = *ratio;
      if (!row.sizes.empty()) {
        entry["sizes"] = row.sizes;
        entry["sizes_from"] = row.sizes_from;
      }
      if (const auto speedup = our_speedup(bench, row)) entry["speedup_vs_serial"] = *speedup;
      if (const auto paper = paper_ms(bench, row.backend)) entry["paper_ms"] = *paper;
      if (const auto speedup = paper_speedup(bench, row.backend)) entry["paper_speedup"] = *speedup;
      rows.push_back(entry);
    }
    out_cases.push_back({{"mesh", bench.mesh}, {"vertices", bench.vertices}, {"n", bench.particles}, {"rows", rows}});
  }
  return {{"device", device_name},
          {"iterations", settings.iterations},
          {"device_scheme", scheme_name(settings.device_scheme)},
          {"colors", uses_colors(settings.device_scheme) ? nlohmann::json(settings.colors) : nullptr},
          {"time", "wall ms per iteration (mean over the timed iterations), after warm-up"},
          {"cases", out_cases}};
}

void write_bench_csv(const std::filesystem::path& file, const std::string& device_name,
                     const BenchSettings& settings, const std::vector<BenchCase>& cases) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "device,mesh,vertices,n,backend,scheme,sizes,sizes_from,iterations,ms_per_iteration,median_ms,min_ms,"
           "kernel_ms,moved_per_iteration,speedup_vs_serial,paper_ms,paper_speedup\n";
    auto optional = [](std::optional<double> value) { return value ? format_number("%.6g", *value) : std::string(); };
    for (const auto& bench : cases) {
      for (const auto& row : bench.rows) {
        out << csv_field(row.kernel_ms ? device_name : kHostDevice) << ',' << bench.mesh << ','
            << bench.vertices << ',' << bench.particles << ',' << row.backend << ',' << scheme_name(row.scheme)
            << ',' << row.sizes << ',' << row.sizes_from << ',' << settings.iterations << ','
            << format_number("%.6g", row.mean_ms) << ',' << format_number("%.6g", row.timing.median_ms) << ','
            << format_number("%.6g", row.timing.min_ms) << ',' << optional(row.kernel_ms) << ','
            << format_number("%.6g", row.moved_mean) << ','
            << optional(our_speedup(bench, row)) << ',' << optional(paper_ms(bench, row.backend)) << ','
            << optional(paper_speedup(bench, row.backend)) << '\n';
      }
    }
  });
}

}  // namespace meshparticles
