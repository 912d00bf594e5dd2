// `meshparticles run`: the whole pipeline - mesh, distance table, start,
// iterations on a backend - and its outputs (particles, CSV, report.json).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "backends/backend_factory.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_loading.hpp"
#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "quality/distribution_quality.hpp"
#include "reports/run_outputs.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct RunOptions {
  std::string mesh;
  std::size_t particles = 1024;
  std::size_t iterations = kDefaultMaxIterations;
  BackendRequest backend;
  std::string scheme;  // default: sequential on the serial backends, colored on devices
  std::optional<unsigned> colors;
  std::string init = "farthest";
  std::optional<std::size_t> start_vertex;
  std::uint64_t seed = 1;
  std::optional<double> sigma;
  std::string potential = "exp";
  std::string geodesic = "fmm";
  std::string out = "out";
  std::string tuning_file;
  DistanceTableOptions table;
};

Scheme chosen_scheme(const RunOptions& options) {
  if (!options.scheme.empty()) return parse_scheme(options.scheme);
  return is_device_backend(options.backend.name) ? Scheme::colored : Scheme::sequential;
}

void check_arguments(const RunOptions& options, const SurfaceMesh& mesh, Scheme scheme, Init init) {
  if (options.particles > mesh.vertex_count()) {
    throw UserError("-n " + std::to_string(options.particles) + " is more particles than the " +
                    std::to_string(mesh.vertex_count()) + " vertices of " + options.mesh);
  }
  if (options.colors && scheme != Scheme::colored) {
    throw UserError("--colors applies to --scheme colored, not " + scheme_name(scheme));
  }
  if (options.start_vertex && init == Init::random) {
    throw UserError("--start-vertex applies to --init v0 and farthest, not random");
  }
}

void print_summary(const RunOptions& options, const nlohmann::json& report, const DistributionQuality& quality) {
  const auto& params = report["params"];
  std::printf("mesh        %s (%zu vertices)\n", options.mesh.c_str(), report["mesh"]["vertices"].get<std::size_t>());
  std::printf("particles   %zu, %s on %s, scheme %s\n", options.particles, options.backend.name.c_str(),
              report["device"].get<std::string>().c_str(), params["scheme"].get<std::string>().c_str());
  std::printf("iterations  %zu (%s)\n", report["iterations_run"].get<std::size_t>(),
              report["stopped"].get<std::string>().c_str());
  std::printf("energy      %.6g -> %.6g\n", report["initial_energy"].get<double>(), report["final_energy"].get<double>());
  std::printf("time        %.3f ms/iteration", report["avg_iteration_ms"].get<double>());
  if (report.contains("avg_kernel_ms")) std::printf(" (update kernels %.3f ms)", report["avg_kernel_ms"].get<double>());
  std::printf("\nquality     %s", quality_line(quality).c_str());
  std::printf("\noutput      %s/{particles.particles, particles.csv, report.json, particles.ply, mesh_distance.vtk}\n",
              options.out.c_str());
}

void run_run(RunOptions options) {
  const Potential potential = parse_potential(options.potential);
  const Scheme scheme = chosen_scheme(options);
  const SurfaceMesh mesh = load_mesh_or_default(options.mesh, options.table.quiet);
  const Init init = parse_init(options.init);
  check_arguments(options, mesh, scheme, init);
  std::optional<VertexId> start_vertex;
  if (options.start_vertex) start_vertex = surface_vertex_for_option(mesh, *options.start_vertex, "--start-vertex");
  prepare_output_directory(options.out);  // before the long work, not after

  options.backend.tuning_file = tuning_file_or_default(options.tuning_file);
  const CheckedBackend checked = check_backend(options.backend, mesh, options.particles);
  if (checked.tuning_refused && !options.table.quiet) {
    std::cerr << "meshparticles: warning: " << checked.sizes_note << "; using the built-in sizes\n";
  }

  const EnergyParams energy{potential, options.sigma.value_or(default_sigma(potential, mesh.area(), options.particles))};
  TableSource table_source;
  const DistanceTable distances =
      load_or_compute_distances(mesh, options.table.request(parse_method(options.geodesic)), table_source);
  const std::unique_ptr<ParticleBackend> backend = make_backend(checked, mesh, distances, energy);

  PlacementRequest placement{init, options.particles, options.seed, start_vertex};
  const std::vector<VertexId> start = place_particles(distances, placement);
  const unsigned colors = options.colors.value_or(kDefaultColors);
  const RunOutcome outcome =
      run_particles(*backend, start, {scheme, colors, options.iterations, options.table.quiet});

  nlohmann::json params = {{"n", options.particles},
                           {"iterations", options.iterations},
                           {"backend", options.backend.name},
                           {"scheme", scheme_name(scheme)},
                           {"init", options.init},
                           {"seed", options.seed},
                           {"sigma", energy.sigma},
                           {"sigma_from", options.sigma ? "--sigma" : "default rule"},
                           {"potential", potential_name(potential)},
                           {"geodesic", options.geodesic},
                           {"out", options.out}};
  if (scheme == Scheme::colored) params["colors"] = colors;
  if (is_field_backend(options.backend.name)) {
    params["weights"] = weight_format_name(checked.weights);
    params["rebuild_every"] = checked.rebuild_every;
  }
  if (start_vertex) params["start_vertex"] = *options.start_vertex;
  if (checked.kernel) {
    params["wg"] = checked.kernel->work_group_size;
    if (checked.kernel->kind == KernelKind::tiled) params["tile"] = checked.kernel->tile_size;
    params["sizes_from"] = checked.sizes_from;
    if (!checked.sizes_note.empty()) params["sizes_note"] = checked.sizes_note;
  }
  nlohmann::json report = run_report(mesh, {options.mesh, params, backend->device_name()}, outcome);
  const std::vector<float> to_nearest = distance_to_nearest_particle(distances, outcome.positions);
  const DistributionQuality quality = measure_quality(mesh, distances, outcome.positions, energy, to_nearest);
  report["quality"] = quality_json(quality);
  write_run_outputs(options.out, mesh, outcome.positions, report, to_nearest);
  print_summary(options, report, quality);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Spread particles over a mesh (default: the sphere, 1024 particles)");
  run->add_option("mesh", options->mesh, "Mesh file (default: meshes/sphere.off, else the built-in sphere)");
  run->add_option("-n,--particles", options->particles, "Number of particles, 1..V")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  run->add_option("--iterations", options->iterations,
                  "Stop after this many iterations (or when none moves); 0 writes the start and its quality")
      ->capture_default_str();
  run->add_option("--backend", options->backend.name,
                  "serial (the reference), serial-field (the field method in plain C++), "
                  "naive, tiled or field (OpenCL)")
      ->check(CLI::IsMember(backend_names()))
      ->capture_default_str();
  run->add_option("--scheme", options->scheme,
                  "sequential, synchronous or colored (default: sequential on serial and serial-field, colored on "
                  "the OpenCL backends)")
      ->check(CLI::IsMember({"sequential", "synchronous", "colored"}));
  run->add_option("--colors", options->colors, "Groups of the colored scheme (default " + std::to_string(kDefaultColors) + ")")->check(CLI::PositiveNumber);
  run->add_option("--init", options->init, "Start: v0 (all on one vertex), random, farthest (farthest-point sampling)")
      ->check(CLI::IsMember({"v0", "random", "farthest"}))
      ->capture_default_str();
  run->add_option("--start-vertex", options->start_vertex, "Input vertex id for v0, or the first farthest sample");
  run->add_option("--seed", options->seed, "Seed of random and farthest starts")->capture_default_str();
  run->add_option("--sigma", options->sigma, "Sigma in mesh units (default from the particle spacing, see docs)")
      ->check(CLI::PositiveNumber);
  run->add_option("--potential", options->potential, "exp: exp(-d/(2 sigma^2)); gauss: exp(-d^2/(2 sigma^2))")
      ->check(CLI::IsMember({"exp", "gauss"}))
      ->capture_default_str();
  run->add_option("--geodesic", options->geodesic, "Distance solver: fmm or dijkstra")
      ->check(CLI::IsMember({"fmm", "dijkstra"}))
      ->capture_default_str();
  add_device_option(*run, options->backend.device);
  run->add_option("--wg", options->backend.work_group_size, "Work-group size of the kernel")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  run->add_option("--tile", options->backend.tile_size, "Tile size (particles staged in local memory; tiled only)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 24));
  run->add_option("--weights", options->backend.weights,
                  "Weight table of the field backends: float (float32, default) or half (half the bytes)")
      ->check(CLI::IsMember({"float", "half"}));
  run->add_option("--rebuild-every", options->backend.rebuild_every,
                  "Field backends: rebuild the field from scratch every N iterations (default 0: never; it is "
                  "exact and does not drift)");
  run->add_option("--out", options->out, "Output directory")->capture_default_str();
  run->add_option("--tuning-file", options->tuning_file,
                  "Sizes saved by `sweep --save`, used when --wg and --tile are absent "
                  "(default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_distance_table_options(*run, options->table);
  run->callback([options] { run_run(*options); });
}

}  // namespace meshparticles
