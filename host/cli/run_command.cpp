// `meshparticles run`: the pipeline (pipeline/run_pipeline.hpp) on one mesh,
// its files (reports/run_outputs.hpp) and a summary on stdout.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "backends/backend_table.hpp"
#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/run_pipeline.hpp"
#include "reports/quality_report.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct RunOptions {
  std::string mesh;
  MeshReadOptions read;
  RunRequest request;
  // Options whose words become enums in the request.
  std::string scheme;  // default: the backend's
  std::string init = "farthest";
  std::string potential = "exp";
  std::string geodesic = "fmm";
  std::string weights;
  DistanceStoreOptions store;
  std::string tuning_file;
  std::string out = "out";
  DistanceTableOptions table;
};

void print_summary(const RunResult& result, const nlohmann::json& report, const std::string& out) {
  const auto& params = report["params"];
  std::printf("mesh        %s (%zu vertices)\n", result.plan.request.mesh_label.c_str(),
              report["mesh"]["vertices"].get<std::size_t>());
  std::printf("particles   %zu, %s on %s, scheme %s\n", result.plan.request.particles,
              params["backend"].get<std::string>().c_str(), report["device"].get<std::string>().c_str(),
              params["scheme"].get<std::string>().c_str());
  std::printf("iterations  %zu (%s)\n", report["iterations_run"].get<std::size_t>(),
              report["stopped"].get<std::string>().c_str());
  std::printf("energy      %.6g -> %.6g\n", report["initial_energy"].get<double>(), report["final_energy"].get<double>());
  std::printf("time        %.3f ms/iteration", report["avg_iteration_ms"].get<double>());
  if (report.contains("avg_kernel_ms")) std::printf(" (update kernels %.3f ms)", report["avg_kernel_ms"].get<double>());
  std::printf("\nquality     %s", quality_line(result.quality).c_str());
  std::printf("\noutput      %s/{particles.particles, particles.csv, report.json, particles.ply, mesh_distance.vtk}\n",
              out.c_str());
}

void run_run(RunOptions options) {
  RunRequest& request = options.request;
  if (!options.scheme.empty()) request.scheme = parse_scheme(options.scheme);
  request.init = parse_init(options.init);
  request.potential = parse_potential(options.potential);
  if (!options.weights.empty()) request.backend.weights = parse_weight_format(options.weights);
  request.backend.tuning_file = tuning_file_or_default(options.tuning_file);
  request.distances = options.store.request(options.table.request(parse_method(options.geodesic)));
  request.quiet = options.table.quiet;

  const SurfaceMesh mesh = load_mesh_or_default(options.mesh, request.quiet, options.read);
  request.mesh_label = options.mesh;
  const RunPlan plan = plan_run(mesh, request);
  prepare_output_directory(options.out);  // before the long work, not after
  const RunResult result = execute_run(mesh, plan);
  const nlohmann::json report = run_report(mesh, result, options.out);
  write_run_outputs(options.out, mesh, result, report);
  print_summary(result, report, options.out);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  RunRequest& request = options->request;
  CLI::App* run = app.add_subcommand("run", "Spread particles over a mesh (default: the sphere, 1024 particles)");
  run->add_option("mesh", options->mesh, "Mesh file (default: meshes/sphere.off, else the built-in sphere)");
  add_whole_number_option(*run, "-n,--particles", request.particles, kParticleRange,
                          "Number of particles, at most the mesh's vertices");
  add_whole_number_option(*run, "--iterations", request.max_iterations, kRunIterationRange,
                          "Stop after this many iterations (or when none moves); 0 writes the start and its quality");
  std::string backends_help;
  for (const BackendDescriptor* backend : backend_table()) {
    backends_help += (backends_help.empty() ? "" : "; ") + backend->name + ": " + backend->summary;
  }
  request.backend.name.clear();  // the default follows the distance store (plan_run)
  run->add_option("--backend", request.backend.name, backends_help)
      ->check(CLI::IsMember(backend_names()))
      ->default_str("field on a dense table, serial-field on local distances");
  run->add_option("--scheme", options->scheme,
                  "sequential, synchronous, colored or monotone (colored, with every iteration lowering the energy; "
                  "default: sequential on serial and serial-field, monotone on the OpenCL backends)")
      ->check(CLI::IsMember({"sequential", "synchronous", "colored", "monotone"}));
  add_whole_number_option(*run, "--colors", request.colors, kColorRange,
                          "Groups of the colored and monotone schemes (default " + std::to_string(kDefaultColors) + ")");
  run->add_option("--init", options->init, "Start: v0 (all on one vertex), random, farthest (farthest-point sampling)")
      ->check(CLI::IsMember({"v0", "random", "farthest"}))
      ->capture_default_str();
  add_whole_number_option(*run, "--start-vertex", request.start_vertex, kVertexIdRange,
                          "Input vertex id for v0, or the first farthest sample");
  add_whole_number_option(*run, "--seed", request.seed, kSeedRange, "Seed of random and farthest starts");
  add_positive_number_option(*run, "--sigma", request.sigma,
                             "Sigma in mesh units (default from the particle spacing, see docs)");
  run->add_option("--potential", options->potential, "exp: exp(-d/(2 sigma^2)); gauss: exp(-d^2/(2 sigma^2))")
      ->check(CLI::IsMember({"exp", "gauss"}))
      ->capture_default_str();
  run->add_option("--geodesic", options->geodesic, "Distance solver: fmm or dijkstra")
      ->check(CLI::IsMember({"fmm", "dijkstra"}))
      ->capture_default_str();
  add_distance_store_options(*run, options->store);
  add_device_option(*run, request.backend.device);
  add_whole_number_option(*run, "--wg", request.backend.work_group_size, kWorkGroupRange,
                          "Work-group size of the kernel");
  add_whole_number_option(*run, "--tile", request.backend.tile_size, kTileRange,
                          "Tile size (particles staged in local memory; tiled only)");
  run->add_option("--weights", options->weights,
                  "Weight table of the field backends: float (float32, default) or half (half the bytes)")
      ->check(CLI::IsMember({"float", "half"}));
  add_whole_number_option(*run, "--rebuild-every", request.backend.rebuild_every, kRebuildRange,
                          "Field backends: rebuild the field from scratch every N iterations (default 0: never; it "
                          "is exact and does not drift)");
  run->add_option("--out", options->out, "Output directory")->capture_default_str();
  run->add_option("--tuning-file", options->tuning_file,
                  "Sizes saved by `sweep --save`, used when --wg and --tile are absent "
                  "(default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_strict_option(*run, options->read);
  add_distance_table_options(*run, options->table);
  run->callback([options] { run_run(*options); });
}

}  // namespace meshparticles
