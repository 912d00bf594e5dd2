// `meshparticles sweep`: time every kernel configuration on one problem,
// each verified against the serial reference first (measurement/sweep.hpp);
// optionally save the best sizes for `run` and `bench` (--save).
#include <algorithm>
#include <iostream>

#include "backends/backend_table.hpp"
#include "cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"
#include "measurement/sweep.hpp"
#include "options/number_options.hpp"
#include "options/option_values.hpp"
#include "particles/potentials.hpp"
#include "pipeline/mesh_input.hpp"
#include "reports/sweep_report.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct SweepOptions {
  std::string mesh;
  MeshReadOptions read;
  SweepRequest request;
  std::vector<std::size_t> tile_sizes = kSweepTileSizes;
  std::string weights = "float";
  std::string scheme = "colored";
  std::string init = "farthest";
  std::string potential = potential_name(kDefaultPotential);
  std::string geodesic = "fmm";
  std::string csv;
  std::string json;
  bool save = false;
  std::string tuning_file;
  DistanceTableOptions table;
};

void save_best(const SweepOutcome& sweep, const std::filesystem::path& file, TuningStore store) {
  const SweepRequest& request = sweep.plan.request;
  bool saved = false;
  for (const std::string& kernel : request.kernels) {
    const SweepResult* best = best_result(sweep.results, kernel);
    if (!best) continue;
    store.put({sweep.plan.device.name, kernel, size_class(request.particles), best->kernel.work_group_size,
               best->kernel.spec().takes_tile ? best->kernel.tile_size : 0, best->timing.median_ms,
               request.mesh_label + " n=" + std::to_string(request.particles)});
    saved = true;
  }
  if (!saved) {
    std::cout << "nothing saved: no configuration was timed\n";
    return;
  }
  store.save(file);
  std::cout << "saved the best sizes for " << sweep.plan.device.name << ", " << size_class(request.particles)
            << " to " << file.string() << "\n";
}

void run_sweep_command(SweepOptions options, bool tiles_given, bool weights_given, bool colors_given) {
  SweepRequest& request = options.request;
  request.settings.scheme = parse_scheme(options.scheme);
  if (colors_given && request.settings.scheme != Scheme::colored) {
    throw UserError("--colors applies to --scheme colored, not " + options.scheme);
  }
  if (tiles_given) request.tile_sizes = options.tile_sizes;
  if (weights_given) request.weights = parse_weight_format(options.weights);
  request.init = parse_init(options.init);
  request.potential = parse_potential(options.potential);
  request.geodesics = options.table.request(parse_method(options.geodesic));
  request.settings.quiet = options.table.quiet;

  const SurfaceMesh mesh = load_mesh_or_default(options.mesh, options.table.quiet, options.read);
  request.mesh_label = options.mesh;
  const SweepPlan plan = plan_sweep(mesh, request);
  // Everything that can fail fast does so before the distances.
  for (const auto& file : {options.csv, options.json}) {
    if (!file.empty()) check_writable(file);
  }
  std::filesystem::path tuning_file;
  TuningStore store;
  if (options.save) {
    tuning_file = tuning_file_or_default(options.tuning_file).value_or("");
    if (tuning_file.empty()) {
      throw UserError("--save: neither $XDG_CONFIG_HOME nor $HOME is set, so there is no default tuning file "
                      "(give --tuning-file)");
    }
    create_directory_for(tuning_file.parent_path(), "tuning file directory");
    check_writable(tuning_file);
    store = TuningStore::load(tuning_file, device_backend_names());  // refuses to overwrite a file it cannot read
  }

  const SweepOutcome sweep = run_sweep(mesh, plan);
  std::cout << sweep_table(sweep);
  if (!options.csv.empty()) write_sweep_csv(options.csv, sweep);
  if (!options.json.empty()) {
    const nlohmann::json document = sweep_json(sweep);
    write_file_atomically(options.json, [&](std::ostream& out) { out << json_text(document, 2) << "\n"; });
  }
  if (options.save) save_best(sweep, tuning_file, store);

  const auto failed = std::count_if(sweep.results.begin(), sweep.results.end(),
                                    [](const SweepResult& r) { return r.status == SweepStatus::failed; });
  if (failed > 0) {
    throw UserError(std::to_string(failed) + " configuration(s) FAILED: the kernel built wrongly or disagrees with "
                    "the serial reference (see the table)", 1);
  }
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto options = std::make_shared<SweepOptions>();
  SweepRequest& request = options->request;
  request.kernels = device_backend_names();
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Time the update kernels over work-group and tile sizes, each verified against the serial reference");
  sweep->add_option("mesh", options->mesh, "Mesh file (default: meshes/sphere.off, else the built-in sphere)");
  add_whole_number_option(*sweep, "-n,--particles", request.particles, kParticleRange,
                          "Number of particles, at most the mesh's vertices");
  add_name_list_option(*sweep, "--kernel", request.kernels, device_backend_names(),
                       "Kernels to sweep, comma-separated");
  add_whole_number_list_option(*sweep, "--wg", request.work_group_sizes, kWorkGroupRange,
                               "Work-group sizes, comma-separated");
  add_whole_number_list_option(*sweep, "--tile", options->tile_sizes, kTileRange,
                               "Tile sizes of the tiled kernel, comma-separated");
  sweep->add_option("--weights", options->weights,
                    "Weight table of the field kernel: float or half (half is held to 1e-3 of the reference, "
                    "not 1e-5)")
      ->check(CLI::IsMember({"float", "half"}))
      ->capture_default_str();
  add_whole_number_option(*sweep, "--iterations", request.settings.repetitions, kTimedIterationRange,
                          "Timed iterations per configuration (after 2 warm-ups)");
  sweep->add_option("--scheme", options->scheme, "synchronous or colored: the launches one iteration makes")
      ->check(CLI::IsMember({"synchronous", "colored"}))
      ->capture_default_str();
  request.settings.colors = kDefaultColors;
  add_whole_number_option(*sweep, "--colors", request.settings.colors, kColorRange, "Groups of the colored scheme");
  sweep->add_option("--init", options->init, "Positions the kernels are timed and verified on")
      ->check(CLI::IsMember({"v0", "random", "farthest"}))
      ->capture_default_str();
  add_whole_number_option(*sweep, "--seed", request.seed, kSeedRange, "Seed of random and farthest starts");
  add_potential_option(*sweep, options->potential);
  add_geodesic_option(*sweep, options->geodesic);
  add_device_option(*sweep, request.device);
  sweep->add_option("--csv", options->csv, "Also write the rows as CSV to this file");
  sweep->add_option("--json", options->json, "Also write the rows and the device's limits as JSON to this file");
  sweep->add_flag("--save", options->save, "Store the best sizes per kernel for this device and size class");
  sweep->add_option("--tuning-file", options->tuning_file,
                    "Where --save stores them (default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_strict_option(*sweep, options->read);
  add_distance_table_options(*sweep, options->table);
  sweep->callback([options, sweep] {
    run_sweep_command(*options, sweep->count("--tile") > 0, sweep->count("--weights") > 0,
                      sweep->count("--colors") > 0);
  });
}

}  // namespace meshparticles
