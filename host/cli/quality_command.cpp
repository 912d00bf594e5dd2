// `meshparticles quality MESH PARTICLES` and `meshparticles compare MESH A B`:
// how evenly particle files (ours or ShapeWorks .particles) cover a mesh,
// one set or two side by side (docs/QUALITY.md).
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/json_text.hpp"
#include "options/number_options.hpp"
#include "particles/potentials.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/point_set_measurement.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

struct QualityOptions {
  std::string mesh;
  MeshReadOptions read;
  std::vector<std::string> particle_files;  // one (quality) or two (compare)
  std::optional<double> sigma;
  std::string potential = potential_name(kDefaultPotential);
  std::string geodesic = "fmm";
  bool json = false;
  std::string refine = "auto";
  DistanceTableOptions table;
  DistanceStoreOptions store;
};

void run_quality(const QualityOptions& options) {
  const SurfaceMesh input = load_mesh(options.mesh, options.table.quiet, options.read);
  PointSetsRequest request;
  request.names = options.particle_files;
  // Read before the distance table, so a bad file fails in a second.
  for (const auto& file : options.particle_files) request.points.push_back(read_particle_points(file));
  set_refinement(request, options.refine);  // the option's validator admits auto, spread or 0..8
  request.geodesics = options.table.request(parse_method(options.geodesic));
  request.distances = options.store.request(request.geodesics);
  request.potential = parse_potential(options.potential);
  request.sigma = options.sigma;
  const PointSetsMeasurement measured = measure_point_sets(input, request);
  if (options.json) {
    std::cout << json_text(point_sets_json(options.mesh, measured), 2) << "\n";
    return;
  }
  const MeasuringMesh& measuring = measured.measuring;
  const SurfaceMesh& mesh = measuring.refined.mesh;
  const std::vector<MeasuredSet>& sets = measured.sets;
  const Potential potential = request.potential;
  std::cout << "mesh " << options.mesh << " (" << input.vertex_count() << " vertices, mean edge "
            << input.mean_edge_length() << "); geodesic distances, " << potential_name(potential) << " potential";
  if (measuring.refined.levels > 0) {
    std::cout << "; measured on " << (measuring.spread ? "spread's working mesh" : "the mesh refined uniformly")
              << " (" << measuring.refined.levels << " rounds, " << mesh.vertex_count() << " vertices)";
  }
  std::cout << "\n\n";
  std::vector<const MeasuredSet*> columns;
  for (const auto& set : sets) columns.push_back(&set);
  std::cout << quality_table(columns);
  if (sets.size() == 2) {
    std::cout << "\nmean distance to the nearest particle of the other set: A -> B " << *measured.mean_a_to_b
              << ", B -> A " << *measured.mean_b_to_a << " (d_hex of A " << sets[0].quality.d_hex << ")\n";
  }
}

void add_shared_options(CLI::App& command, QualityOptions& options) {
  add_positive_number_option(command, "--sigma", options.sigma,
                             "Sigma of the energy (default: the run's rule for each set's n)");
  add_potential_option(command, options.potential);
  add_geodesic_option(command, options.geodesic);
  command.add_flag("--json", options.json, "Machine-readable output");
  add_strict_option(command, options.read);
  add_distance_store_options(command, options.store);
  add_distance_table_options(command, options.table);
  command
      .add_option("--refine", options.refine,
                  "The mesh the points are measured on, points between its vertices inserted as vertices: auto "
                  "(the mesh itself if every point lies on its vertices, else spread's working mesh), spread (that "
                  "working mesh), or 0 to 8 uniform midpoint rounds")
      ->check(CLI::IsMember({"auto", "spread", "0", "1", "2", "3", "4", "5", "6", "7", "8"}))
      ->capture_default_str();
}

}  // namespace

void add_quality_command(CLI::App& app) {
  auto options = std::make_shared<QualityOptions>();
  CLI::App* quality = app.add_subcommand(
      "quality", "How evenly a particle file covers a mesh: nearest-neighbour distances, packing and covering radii, "
                 "energy (points between vertices are measured where they are, inserted as vertices of a refined mesh)");
  quality->add_option("mesh", options->mesh, "Mesh file")->required();
  quality->add_option("particles", options->particle_files, "Particle file: one \"x y z\" per line (.particles)")
      ->required()
      ->expected(1);
  add_shared_options(*quality, *options);
  quality->callback([options] { run_quality(*options); });
}

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<QualityOptions>();
  CLI::App* compare = app.add_subcommand(
      "compare", "Two particle files on one mesh side by side, and how far each set's particles are from the other's");
  compare->add_option("mesh", options->mesh, "Mesh file")->required();
  compare->add_option("particles", options->particle_files, "Particle files A and B (.particles)")
      ->required()
      ->expected(2);
  add_shared_options(*compare, *options);
  compare->callback([options] { run_quality(*options); });
}

}  // namespace meshparticles
