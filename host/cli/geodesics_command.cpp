#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include "cli/commands.hpp"
#include "options/number_options.hpp"
#include "pipeline/mesh_input.hpp"
#include "common/atomic_file.hpp"
#include "common/user_error.hpp"
#include "geodesics/device_balls.hpp"
#include "geodesics/distance_cache.hpp"
#include "geodesics/local_distances.hpp"
#include "geodesics/solver_factory.hpp"

namespace meshparticles {

namespace {

struct GeodesicsOptions {
  std::string mesh;
  MeshReadOptions read;
  std::optional<std::size_t> source;
  std::string out;
  std::string method = "fmm";
  DistanceTableOptions table;
  std::optional<std::size_t> balls;  // solve this many balls instead of the table
  std::optional<double> ball_radius;
  bool on_host = false;
  std::string device;
};

// One value per line, one line per vertex of the input file (input ids);
// a vertex the reader dropped (no face uses it) is not on the surface: inf.
void write_single_source(const SurfaceMesh& mesh, const std::vector<double>& distances, std::ostream& out) {
  char line[32];
  for (std::size_t input_id = 0; input_id < mesh.input_vertex_count(); ++input_id) {
    const auto v = mesh.vertex_of_input_id(input_id);
    const double d = v ? distances[*v] : INFINITY;
    std::snprintf(line, sizeof line, "%.9g\n", d);
    out << line;
  }
}

// Every vertex id from 0 in steps of V / count: `count` sources spread over the mesh.
std::vector<VertexId> spread_sources(const SurfaceMesh& mesh, std::size_t count) {
  std::vector<VertexId> sources(count);
  for (std::size_t k = 0; k < count; ++k) sources[k] = VertexId(k * mesh.vertex_count() / count);
  return sources;
}

// The relative error of `balls` against fast marching's balls of the same
// sources, over the vertices both hold farther than three mean edges from
// the source (nearer ones are dominated by discretisation), on a sample.
void print_error_against_fast_marching(const SurfaceMesh& mesh, std::span<const VertexId> sources,
                                       const std::vector<Ball>& balls, double radius) {
  constexpr std::size_t kSample = 64;
  const auto fast_marching = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  double sum = 0, worst = 0;
  std::size_t count = 0;
  const std::size_t step = std::max<std::size_t>(1, sources.size() / kSample);
  for (std::size_t k = 0; k < sources.size(); k += step) {
    const Ball reference = fast_marching->solve_ball(sources[k], radius, scratch);
    for (std::size_t i = 0; i < reference.vertices.size(); ++i) {
      const std::optional<float> d = distance_in_ball(balls[k], reference.vertices[i]);
      const double truth = reference.distances[i];
      if (!d || truth <= 3 * mesh.mean_edge_length()) continue;
      const double error = std::abs(double(*d) - truth) / truth;
      sum += error;
      worst = std::max(worst, error);
      ++count;
    }
  }
  std::printf("against fmm %.4f%% mean, %.4f%% largest relative difference (%zu distances of %zu balls)\n",
              count ? 100 * sum / double(count) : 0.0, 100 * worst, count, (sources.size() + step - 1) / step);
}

// --balls: `count` balls of one radius, timed, on the device (fim) or on all cores.
void run_balls(const SurfaceMesh& mesh, const GeodesicsOptions& options, GeodesicMethod method) {
  const double radius = *options.ball_radius;
  const std::vector<VertexId> sources = spread_sources(mesh, *options.balls);
  std::vector<Ball> balls(sources.size());
  const auto started = std::chrono::steady_clock::now();
  if (method == GeodesicMethod::fast_iterative && !options.on_host) {
    const DeviceDescription device = select_device(options.device);
    const FastIterativeMethod host(mesh);
    DeviceBallSolver solver(mesh, host, device);
    const double set_up = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    balls = solver.solve_balls(sources, radius);
    const auto& statistics = solver.statistics();
    std::printf("device     %s (table of %zu vertices, work-group %zu)\n", device.name.c_str(), solver.slots(),
                solver.work_group_size());
    std::printf("set-up     %.3f s (stencils, program, uploads)\n", set_up);
    std::printf("balls      %.3f s, kernels %.3f s, %zu launches, %zu solved on the host\n", statistics.seconds,
                statistics.kernel_seconds, statistics.launches, statistics.solved_on_host);
  } else {
    LocalDistances::Settings settings;
    settings.radius = radius;
    settings.method = method;
    settings.cache_bytes = std::numeric_limits<std::uint64_t>::max();
    settings.threads = options.table.threads;
    settings.quiet = options.table.quiet;
    const LocalDistances store(mesh, settings);
    const auto solving = std::chrono::steady_clock::now();
    store.prefetch(sources);
    std::printf("host       %u threads\n", store.threads());
    std::printf("balls      %.3f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - solving).count());
    for (std::size_t k = 0; k < sources.size(); ++k) balls[k] = *store.ball(sources[k]);
  }
  std::uint64_t entries = 0;
  for (const Ball& ball : balls) entries += ball.vertices.size();
  std::printf("solver     %s\n", options.method.c_str());
  std::printf("count      %zu balls of radius %g, %.0f vertices on average\n", balls.size(), radius,
              double(entries) / double(std::max<std::size_t>(balls.size(), 1)));
  if (method != GeodesicMethod::fast_marching) print_error_against_fast_marching(mesh, sources, balls, radius);
}

void run_geodesics(const GeodesicsOptions& options) {
  const SurfaceMesh mesh = load_mesh(options.mesh, options.table.quiet, options.read);
  const GeodesicMethod method = parse_method(options.method);
  const auto started = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };

  if (options.balls) {
    run_balls(mesh, options, method);
    return;
  }
  if (options.source) {
    const VertexId source = surface_vertex_for_option(mesh, *options.source, "--source");
    std::vector<double> distances(mesh.vertex_count());
    SolverScratch scratch;
    make_geodesic_solver(mesh, method)->solve(source, distances, scratch);
    if (options.out.empty()) {
      write_single_source(mesh, distances, std::cout);
    } else {
      write_file_atomically(options.out, [&](std::ostream& out) { write_single_source(mesh, distances, out); });
    }
    if (!options.table.quiet) std::fprintf(stderr, "one source with %s in %.3f ms\n", options.method.c_str(), 1e3 * seconds_since_start());
    return;
  }

  TableSource source;
  const DistanceTable table = load_or_compute_distances(mesh, options.table.request(method), source);
  std::printf("table      %zu x %zu float32 (%.1f MiB)\n", table.vertex_count(), table.vertex_count(),
              double(table.byte_size()) / (1 << 20));
  std::printf("solver     %s\n", options.method.c_str());
  std::printf("time       %.2f s\n", seconds_since_start());
  std::printf("from cache %s\n", source.from_cache ? "yes" : "no");
  if (!source.cache_file.empty()) std::printf("cache file %s\n", source.cache_file.c_str());
}

}  // namespace

void add_geodesics_command(CLI::App& app) {
  auto options = std::make_shared<GeodesicsOptions>();
  CLI::App* geodesics = app.add_subcommand("geodesics", "All-pairs geodesic distances (cached), or one source's");
  geodesics->add_option("mesh", options->mesh, "Mesh file")->required();
  auto* source = add_whole_number_option(*geodesics, "--source", options->source, kVertexIdRange,
                                         "Write this vertex's distances (input vertex id)");
  geodesics->add_option("--out", options->out, "File for --source's distances (default: stdout)")->needs(source);
  add_geodesic_option(*geodesics, options->method);
  auto* balls = add_whole_number_option(*geodesics, "--balls", options->balls, kVertexIdRange,
                                        "Solve this many balls (sources spread over the mesh) and time them, "
                                        "with fim on the device");
  add_positive_number_option(*geodesics, "--ball-radius", options->ball_radius, "The balls' radius (mesh units)")
      ->needs(balls);
  balls->needs("--ball-radius");
  geodesics->add_flag("--host", options->on_host, "--balls with fim: on the host's cores, not the device")
      ->needs(balls);
  add_device_option(*geodesics, options->device);
  add_strict_option(*geodesics, options->read);
  add_distance_table_options(*geodesics, options->table);
  geodesics->callback([options] { run_geodesics(*options); });
}

}  // namespace meshparticles
