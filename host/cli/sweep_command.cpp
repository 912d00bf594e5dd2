// `meshparticles sweep`: time every kernel configuration on one problem,
// each verified against the serial reference first; optionally save the best
// sizes for `run` and `bench` (--save).
#include <algorithm>
#include <iostream>
#include <set>

#include "backends/device_backend.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_loading.hpp"
#include "common/atomic_file.hpp"
#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"
#include "particles/initial_placement.hpp"
#include "reports/sweep_report.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct SweepOptions {
  std::string mesh;
  std::size_t particles = 1024;
  std::vector<std::string> kernels = {"naive", "tiled", "field"};
  std::vector<std::size_t> work_group_sizes = {8, 16, 32, 64, 128, 256};
  std::vector<std::size_t> tile_sizes = {16, 32, 64, 128, 256, 512, 1024};
  bool tiles_given = false;
  std::string weights = "float";
  bool weights_given = false;
  std::size_t iterations = 20;
  std::string scheme = "colored";
  unsigned colors = kDefaultColors;
  std::string init = "farthest";
  std::uint64_t seed = 1;
  std::string potential = "exp";
  std::string geodesic = "fmm";
  std::string device;
  std::string csv;
  std::string json;
  bool save = false;
  std::string tuning_file;
  DistanceTableOptions table;
};

template <typename T>
std::vector<T> unique_in_order(const std::vector<T>& values) {
  std::vector<T> unique;
  std::set<T> seen;
  for (const T& value : values) {
    if (seen.insert(value).second) unique.push_back(value);
  }
  return unique;
}

void save_best(const SweepOptions& options, const std::filesystem::path& file, TuningStore store,
               const DeviceDescription& device, const std::vector<SweepResult>& results) {
  bool saved = false;
  for (const KernelKind kind : {KernelKind::naive, KernelKind::tiled, KernelKind::field}) {
    const SweepResult* best = best_result(results, kind);
    if (!best) continue;
    store.put({device.name, kind, size_class(options.particles), best->kernel.work_group_size,
               best->kernel.tile_size, best->timing.median_ms,
               options.mesh + " n=" + std::to_string(options.particles)});
    saved = true;
  }
  if (!saved) {
    std::cout << "nothing saved: no configuration was timed\n";
    return;
  }
  store.save(file);
  std::cout << "saved the best sizes for " << device.name << ", " << size_class(options.particles) << " to "
            << file.string() << "\n";
}

void run_sweep_command(SweepOptions options, bool colors_given) {
  const Potential potential = parse_potential(options.potential);
  const Scheme scheme = parse_scheme(options.scheme);
  if (colors_given && scheme != Scheme::colored) throw UserError("--colors applies to --scheme colored, not " + options.scheme);
  std::vector<KernelKind> kinds;
  for (const auto& name : unique_in_order(options.kernels)) kinds.push_back(parse_kernel_kind(name));
  const bool any_tiled = std::find(kinds.begin(), kinds.end(), KernelKind::tiled) != kinds.end();
  if (options.tiles_given && !any_tiled) throw UserError("--tile applies to the tiled kernel, which is not swept");
  const bool any_field = std::find(kinds.begin(), kinds.end(), KernelKind::field) != kinds.end();
  if (options.weights_given && !any_field) throw UserError("--weights applies to the field kernel, which is not swept");
  if (options.iterations == 0) throw UserError("--iterations must be at least 1 (timed iterations per configuration)");
  const SurfaceMesh mesh = load_mesh_or_default(options.mesh, options.table.quiet);
  if (options.particles > mesh.vertex_count()) {
    throw UserError("-n " + std::to_string(options.particles) + " is more particles than the " +
                    std::to_string(mesh.vertex_count()) + " vertices of " + options.mesh);
  }
  // Everything that can fail fast does so before the distance table.
  for (const auto& file : {options.csv, options.json}) {
    if (!file.empty()) check_writable(file);
  }
  const std::filesystem::path tuning_file = tuning_file_or_default(options.tuning_file);
  const TuningStore store = options.save ? TuningStore::load(tuning_file) : TuningStore();
  const DeviceDescription device = select_device(options.device);

  const EnergyParams energy{potential, default_sigma(potential, mesh.area(), options.particles)};
  TableSource table_source;
  const DistanceTable distances =
      load_or_compute_distances(mesh, options.table.request(parse_method(options.geodesic)), table_source);
  const std::vector<VertexId> positions =
      place_particles(distances, {parse_init(options.init), options.particles, options.seed, std::nullopt});

  const SweepSettings settings{scheme, options.colors, options.iterations, 2, options.table.quiet};
  auto configurations = sweep_configurations(kinds, unique_in_order(options.work_group_sizes),
                                             unique_in_order(options.tile_sizes), mesh.max_valence() + 1);
  for (UpdateKernel& kernel : configurations) {
    if (kernel.kind == KernelKind::field) kernel.weights = parse_weight_format(options.weights);
  }
  const std::vector<SweepResult> results =
      run_sweep(device, mesh, distances, energy, positions, configurations, settings);

  const SweepContext context{options.mesh, mesh.vertex_count(), options.particles, settings};
  std::cout << sweep_table(device, context, results);
  if (!options.csv.empty()) write_sweep_csv(options.csv, device, context, results);
  if (!options.json.empty()) {
    const nlohmann::json document = sweep_json(device, context, results);
    write_file_atomically(options.json, [&](std::ostream& out) { out << document.dump(2) << "\n"; });
  }
  if (options.save) save_best(options, tuning_file, store, device, results);

  const auto failed = std::count_if(results.begin(), results.end(),
                                    [](const SweepResult& r) { return r.status == SweepStatus::failed; });
  if (failed > 0) {
    throw UserError(std::to_string(failed) + " configuration(s) FAILED: the kernel built wrongly or disagrees with "
                    "the serial reference (see the table)", 1);
  }
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Time the update kernels over work-group and tile sizes, each verified against the serial reference");
  sweep->add_option("mesh", options->mesh, "Mesh file (default: meshes/sphere.off, else the built-in sphere)");
  sweep->add_option("-n,--particles", options->particles, "Number of particles, 1..V")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sweep->add_option("--kernel", options->kernels, "Kernels to sweep, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"naive", "tiled", "field"}))
      ->capture_default_str();
  sweep->add_option("--wg", options->work_group_sizes, "Work-group sizes, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20))
      ->capture_default_str();
  sweep->add_option("--tile", options->tile_sizes, "Tile sizes of the tiled kernel, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 24))
      ->capture_default_str()
      ->each([options](const std::string&) { options->tiles_given = true; });
  sweep->add_option("--weights", options->weights,
                    "Weight table of the field kernel: float or half (half is held to 1e-3 of the reference, "
                    "not 1e-5)")
      ->check(CLI::IsMember({"float", "half"}))
      ->capture_default_str()
      ->each([options](const std::string&) { options->weights_given = true; });
  sweep->add_option("--iterations", options->iterations, "Timed iterations per configuration (after 2 warm-ups)")
      ->capture_default_str();
  sweep->add_option("--scheme", options->scheme, "synchronous or colored: the launches one iteration makes")
      ->check(CLI::IsMember({"synchronous", "colored"}))
      ->capture_default_str();
  sweep->add_option("--colors", options->colors, "Groups of the colored scheme")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sweep->add_option("--init", options->init, "Positions the kernels are timed and verified on")
      ->check(CLI::IsMember({"v0", "random", "farthest"}))
      ->capture_default_str();
  sweep->add_option("--seed", options->seed, "Seed of random and farthest starts")->capture_default_str();
  sweep->add_option("--potential", options->potential, "exp or gauss")
      ->check(CLI::IsMember({"exp", "gauss"}))
      ->capture_default_str();
  sweep->add_option("--geodesic", options->geodesic, "Distance solver: fmm or dijkstra")
      ->check(CLI::IsMember({"fmm", "dijkstra"}))
      ->capture_default_str();
  add_device_option(*sweep, options->device);
  sweep->add_option("--csv", options->csv, "Also write the rows as CSV to this file");
  sweep->add_option("--json", options->json, "Also write the rows and the device's limits as JSON to this file");
  sweep->add_flag("--save", options->save, "Store the best sizes per kernel for this device and size class");
  sweep->add_option("--tuning-file", options->tuning_file,
                    "Where --save stores them (default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_distance_table_options(*sweep, options->table);
  sweep->callback([options, sweep] { run_sweep_command(*options, sweep->count("--colors") > 0); });
}

}  // namespace meshparticles
