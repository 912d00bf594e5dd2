#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "pipeline/mesh_input.hpp"
#include "common/atomic_file.hpp"
#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"

namespace meshparticles {

namespace {

struct GeodesicsOptions {
  std::string mesh;
  MeshReadOptions read;
  std::optional<std::size_t> source;
  std::string out;
  std::string method = "fmm";
  DistanceTableOptions table;
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

void run_geodesics(const GeodesicsOptions& options) {
  const SurfaceMesh mesh = load_mesh(options.mesh, options.table.quiet, options.read);
  const GeodesicMethod method = parse_method(options.method);
  const auto started = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };

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
  add_strict_option(*geodesics, options->read);
  add_distance_table_options(*geodesics, options->table);
  geodesics->callback([options] { run_geodesics(*options); });
}

}  // namespace meshparticles
