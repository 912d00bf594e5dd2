#include "cli/run_options.hpp"

#include "backends/backend_table.hpp"
#include "cli/number_options.hpp"
#include "cli/run_option_table.hpp"
#include "pipeline/spread_method.hpp"
#include "common/text_format.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

RunRequest RunOptions::resolved_request() const {
  RunRequest resolved = request;
  if (!scheme.empty()) resolved.scheme = parse_scheme(scheme);
  resolved.init = parse_init(init);
  if (!method.empty()) resolved.method = parse_method_option(method);
  resolved.potential = parse_potential(potential);
  if (!weights.empty()) resolved.backend.weights = parse_weight_format(weights);
  resolved.backend.tuning_file = tuning_file_or_default(tuning_file);
  resolved.distances = store.request(table.request(parse_method(geodesic.empty() ? "fmm" : geodesic)));
  resolved.geodesic_given = !geodesic.empty();
  resolved.distances.geodesics.device = request.backend.device;
  resolved.quiet = table.quiet;
  return resolved;
}

void add_run_options(CLI::App& command, RunOptions& options) {
  RunRequest& request = options.request;
  add_whole_number_option(command, "-n,--particles", request.particles, run_option("particles").range,
                          "Number of particles, at most the mesh's vertices");
  command.add_option("--method", options.method,
                     "spread: farthest-point optimization on the surface refined to enough vertices per particle, "
                     "the evenest spacing (default); paper: the paper's energy and one-ring moves on the mesh's "
                     "vertices (implied by --backend, --scheme, --colors, --weights, --rebuild-every, --wg, --tile "
                     "or --init v0)")
      ->check(CLI::IsMember(run_option("method").words));
  add_positive_number_option(command, "--vertices-per-particle", request.vertices_per_particle,
                             "spread: refine the mesh until it has this many vertices per particle (default " +
                                 format_number("%g", kSpreadVerticesPerParticle) +
                                 "; more spreads further at a larger cover and cost)");
  add_whole_number_option(command, "--relax-rounds", request.relax_rounds, run_option("relax-rounds").range,
                          "spread: at most this many rounds pushing all particles apart at once, off the vertices, "
                          "after the sweeps (default " + std::to_string(kSpreadRelaxRounds) +
                              "); where that is not kept, an evening step moves them one by one; 0: neither, the "
                              "sweeps' vertices");
  add_whole_number_option(command, "--iterations", request.max_iterations, run_option("iterations").range,
                          "Stop after this many iterations (spread: sweeps), or when nothing moves; 0 writes the "
                          "start and its quality");
  std::string backends_help;
  for (const BackendDescriptor* backend : backend_table()) {
    backends_help += (backends_help.empty() ? "" : "; ") + backend->name + ": " + backend->summary;
  }
  request.backend.name.clear();  // the default follows the distance store (plan_run)
  command.add_option("--backend", request.backend.name, backends_help)
      ->check(CLI::IsMember(run_option("backend").words))
      ->default_str("field on a dense table, serial-field on local distances");
  command.add_option("--scheme", options.scheme,
                  "sequential, synchronous, colored or monotone (colored, with every iteration lowering the energy; "
                  "default: sequential on serial and serial-field, monotone on the OpenCL backends)")
      ->check(CLI::IsMember(run_option("scheme").words));
  add_whole_number_option(command, "--colors", request.colors, run_option("colors").range,
                          "Groups of the colored and monotone schemes (default " + std::to_string(kDefaultColors) + ")");
  command.add_option("--init", options.init, "Start: v0 (all on one vertex), random, farthest (farthest-point sampling)")
      ->check(CLI::IsMember(run_option("init").words))
      ->capture_default_str();
  add_whole_number_option(command, "--start-vertex", request.start_vertex, run_option("start-vertex").range,
                          "Input vertex id for v0, or the first farthest sample");
  add_whole_number_option(command, "--seed", request.seed, run_option("seed").range, "Seed of random and farthest starts");
  add_positive_number_option(command, "--sigma", request.sigma,
                             "Sigma in mesh units (default from the particle spacing, see docs)");
  add_potential_option(command, options.potential);
  add_geodesic_option(command, options.geodesic,
                      "default fmm, or fim where the paper method's default backend gives a GPU the balls of local "
                      "distances");
  add_distance_store_options(command, options.store);
  add_device_option(command, request.backend.device);
  add_whole_number_option(command, "--wg", request.backend.work_group_size, run_option("wg").range,
                          "Work-group size of the kernel");
  add_whole_number_option(command, "--tile", request.backend.tile_size, run_option("tile").range,
                          "Tile size (particles staged in local memory; tiled only)");
  command.add_option("--weights", options.weights,
                  "Weight table of the field backends: float (float32, default) or half (half the bytes)")
      ->check(CLI::IsMember(run_option("weights").words));
  add_whole_number_option(command, "--rebuild-every", request.backend.rebuild_every, run_option("rebuild-every").range,
                          "Field backends: rebuild the field from scratch every N iterations (default 0: never; it "
                          "is exact and does not drift)");
  command.add_option("--tuning-file", options.tuning_file,
                     "Sizes saved by `sweep --save`, used when --wg and --tile are absent "
                     "(default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_strict_option(command, options.read);
  add_distance_table_options(command, options.table);
}

}  // namespace meshparticles
