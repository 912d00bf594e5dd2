// `meshparticles bench`: the paper's Tables 1 and 2 on the committed meshes,
// our serial, naive, tiled and field rows beside the paper's figures.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

#include "backends/backend_factory.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_loading.hpp"
#include "common/atomic_file.hpp"
#include "common/progress.hpp"
#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"
#include "mesh/mesh_generator.hpp"
#include "particles/particle_run.hpp"
#include "quality/quality_bench.hpp"
#include "reports/bench_report.hpp"
#include "tuning/paper_figures.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct BenchOptions {
  std::vector<std::string> cases;  // "mesh:n"; default: the paper's
  std::vector<std::string> backends = BenchSettings().backends;
  std::size_t iterations = 20;
  std::string scheme = "colored";
  unsigned colors = kDefaultColors;
  std::string device;
  std::string meshes_dir = "meshes";
  std::string csv;
  std::string json;
  std::string tuning_file;
  bool quality = false;
  DistanceTableOptions table;
};

struct CaseRequest {
  std::string mesh;
  std::size_t particles;
};

std::vector<CaseRequest> requested_cases(const BenchOptions& options) {
  std::vector<CaseRequest> cases;
  if (options.cases.empty() && options.quality) {  // each committed mesh at its largest paper case
    return {{"sphere", 1024}, {"torus", 512}, {"atrium", 1024}, {"patch", 100}};
  }
  if (options.cases.empty()) {
    for (const auto& figures : paper_figures()) cases.push_back({figures.mesh, figures.particles});
    return cases;
  }
  for (const std::string& text : options.cases) {
    const auto colon = text.find(':');
    std::size_t particles = 0;
    try {
      std::size_t used = 0;
      if (colon != std::string::npos) particles = std::stoull(text.substr(colon + 1), &used);
      if (used == 0 || colon + 1 + used != text.size()) particles = 0;
    } catch (const std::exception&) {
      particles = 0;
    }
    if (colon == 0 || particles == 0) throw UserError("--case '" + text + "': expected MESH:N, e.g. sphere:1024");
    cases.push_back({text.substr(0, colon), particles});
  }
  return cases;
}

// The committed mesh of that name; the built-in generator's when the
// directory does not have it (outside the repository).
SurfaceMesh bench_mesh(const BenchOptions& options, const std::string& name) {
  const std::filesystem::path file = std::filesystem::path(options.meshes_dir) / (name + ".off");
  if (std::filesystem::exists(file)) return load_mesh(file, options.table.quiet);
  const auto& names = generated_mesh_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw UserError("--case: no mesh " + file.string() + " and no built-in mesh named '" + name + "'");
  }
  return generate_mesh(name);
}

void run_bench(const BenchOptions& options, bool colors_given) {
  if (colors_given && options.scheme != "colored") {
    throw UserError("--colors applies to --scheme colored, not " + options.scheme);
  }
  BenchSettings settings;
  settings.backends = options.backends;
  settings.device_scheme = parse_scheme(options.scheme);
  settings.colors = options.colors;
  settings.iterations = options.iterations;
  if (settings.iterations == 0) throw UserError("--iterations must be at least 1");
  if (options.quality && !options.csv.empty()) throw UserError("--csv applies to the timing tables (with --quality, use --json)");
  for (const auto& file : {options.csv, options.json}) {
    if (!file.empty()) check_writable(file);
  }
  const std::vector<CaseRequest> requests = requested_cases(options);

  // Meshes loaded and backends checked (sizes from the tuning file) before
  // any timing: refused sizes fail now, not after minutes.
  BackendRequest backend_request;
  backend_request.device = options.device;
  backend_request.tuning_file = tuning_file_or_default(options.tuning_file);
  std::map<std::string, SurfaceMesh> meshes;
  std::vector<std::vector<CheckedBackend>> checked(requests.size());
  std::string device_name = "serial";
  for (std::size_t r = 0; r < requests.size(); ++r) {
    const CaseRequest& request = requests[r];
    if (!meshes.contains(request.mesh)) meshes.emplace(request.mesh, bench_mesh(options, request.mesh));
    const SurfaceMesh& mesh = meshes.at(request.mesh);
    if (request.particles > mesh.vertex_count()) {
      throw UserError("--case " + request.mesh + ":" + std::to_string(request.particles) +
                      " is more particles than its " + std::to_string(mesh.vertex_count()) + " vertices");
    }
    for (const auto& backend : settings.backends) {
      backend_request.name = backend;
      checked[r].push_back(check_backend(backend_request, mesh, request.particles));
      if (checked[r].back().device) device_name = checked[r].back().device->name;
    }
  }

  const std::size_t rows_per_case = settings.backends.size() + (options.quality ? 3 : 0);
  ProgressLine progress("bench", requests.size() * rows_per_case, options.table.quiet);
  std::vector<BenchCase> results;
  std::vector<QualityCase> quality_results;
  std::size_t done = 0;
  std::string current_mesh;
  std::optional<DistanceTable> distances;
  for (std::size_t r = 0; r < requests.size(); ++r) {
    const CaseRequest& request = requests[r];
    const SurfaceMesh& mesh = meshes.at(request.mesh);
    if (request.mesh != current_mesh) {  // one table in memory at a time
      distances.reset();
      TableSource source;
      DistanceTableOptions table = options.table;
      table.quiet = true;  // the bench's own progress line is enough
      progress.update(done, request.mesh + " distances");
      distances.emplace(load_or_compute_distances(mesh, table.request(GeodesicMethod::fast_marching), source));
      current_mesh = request.mesh;
    }
    const auto on_row = [&](const std::string& what) { progress.update(done++, what); };
    if (options.quality) {
      quality_results.push_back(
          quality_case(request.mesh, mesh, *distances, request.particles, checked[r], kDefaultMaxIterations, on_row));
    } else {
      results.push_back(bench_case(request.mesh, mesh, *distances, request.particles, checked[r], settings, on_row));
    }
  }
  progress.update(done);
  progress.finish();
  if (options.quality) {
    std::cout << quality_tables(quality_results);
    if (!options.json.empty()) {
      write_file_atomically(options.json, [&](std::ostream& out) { out << quality_bench_json(quality_results).dump(2) << "\n"; });
    }
    return;
  }

  std::cout << bench_tables(device_name, settings, results);
  if (!options.csv.empty()) write_bench_csv(options.csv, device_name, settings, results);
  if (!options.json.empty()) {
    const nlohmann::json document = bench_json(device_name, settings, results);
    write_file_atomically(options.json, [&](std::ostream& out) { out << document.dump(2) << "\n"; });
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand(
      "bench", "The paper's Tables 1 and 2: time per iteration of serial, naive, tiled and field beside the paper's");
  bench->add_option("--case", options->cases,
                    "MESH:N, comma-separated (default: the paper's sphere 128..1024, torus 128..512, "
                    "atrium 256..1024)")
      ->delimiter(',')
      ->allow_extra_args(false);
  bench->add_option("--backend", options->backends, "Rows, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(backend_names()))
      ->capture_default_str();
  bench->add_option("--iterations", options->iterations, "Timed iterations per row (the paper: 1000)")
      ->capture_default_str();
  bench->add_option("--scheme", options->scheme, "Scheme of the device rows: colored or synchronous")
      ->check(CLI::IsMember({"synchronous", "colored"}))
      ->capture_default_str();
  bench->add_option("--colors", options->colors, "Groups of the colored scheme")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  add_device_option(*bench, options->device);
  bench->add_option("--meshes-dir", options->meshes_dir, "Where the committed meshes are")->capture_default_str();
  bench->add_option("--csv", options->csv, "Also write the rows as CSV to this file");
  bench->add_option("--json", options->json, "Also write the rows as JSON to this file");
  bench->add_flag("--quality", options->quality,
                  "Instead of timing: the quality of random, farthest-point, the paper's start with its sequential "
                  "loop, and the default run on each backend (default cases: sphere:1024, torus:512, atrium:1024, "
                  "patch:100)");
  bench->add_option("--tuning-file", options->tuning_file,
                    "Sizes saved by `sweep --save` (default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_distance_table_options(*bench, options->table);
  bench->callback([options, bench] { run_bench(*options, bench->count("--colors") > 0); });
}

}  // namespace meshparticles
