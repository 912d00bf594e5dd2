// `meshparticles quality MESH PARTICLES` and `meshparticles compare MESH A B`:
// how evenly particle files (ours or ShapeWorks .particles) cover a mesh,
// one set or two side by side (docs/QUALITY.md).
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "pipeline/mesh_input.hpp"
#include "common/user_error.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/sigma_check.hpp"
#include "quality/particle_sets.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

struct QualityOptions {
  std::string mesh;
  MeshReadOptions read;
  std::vector<std::string> particle_files;  // one (quality) or two (compare)
  std::optional<double> sigma;
  std::string potential = "exp";
  std::string geodesic = "fmm";
  bool json = false;
  std::string refine = "auto";
  DistanceTableOptions table;
  DistanceStoreOptions store;
};

std::optional<unsigned> uniform_levels(const std::string& refine) {
  if (refine == "auto" || refine == "spread") return std::nullopt;
  return unsigned(std::stoul(refine));  // the option's validator admits auto, spread or 0..8
}

void run_quality(const QualityOptions& options) {
  const SurfaceMesh input = load_mesh(options.mesh, options.table.quiet, options.read);
  // Read before the distance table, so a bad file fails in a second.
  std::vector<std::vector<Vec3>> points;
  for (const auto& file : options.particle_files) points.push_back(read_particle_points(file));
  if (options.sigma) check_sigma_computable({parse_potential(options.potential), *options.sigma});
  // Points between the input's vertices are measured where they lie on vertices.
  const MeasuringMesh measuring =
      measuring_mesh(input, points, uniform_levels(options.refine), options.refine == "spread");
  const SurfaceMesh& mesh = measuring.refined.mesh;
  const GeodesicMethod method = parse_method(options.geodesic);
  // A local store's cutoff scales with the spacing of the set with the fewest particles (the widest).
  std::size_t fewest = points.front().size();
  for (const auto& set : points) fewest = std::min(fewest, set.size());
  const GeodesicsRequest geodesics = options.table.request(method);
  const DistancesRequest request = options.store.request(geodesics);
  const ObtainedDistances obtained =
      obtain_distances(mesh, geodesics, plan_distances(mesh, request, std::min(fewest, mesh.vertex_count()), false));
  const DistanceStore& distances = *obtained.store;
  const Potential potential = parse_potential(options.potential);
  std::vector<MeasuredSet> sets;
  for (std::size_t k = 0; k < points.size(); ++k) {
    sets.push_back(
        measure_particle_file(mesh, distances, method, options.particle_files[k], points[k], potential, options.sigma,
                              options.table.quiet));
  }
  const bool comparing = sets.size() == 2;
  double a_to_b = 0, b_to_a = 0;
  if (comparing) {
    a_to_b = mean_distance_to_nearest(mesh, method, sets[0].snapped.positions, sets[1].snapped.positions);
    b_to_a = mean_distance_to_nearest(mesh, method, sets[1].snapped.positions, sets[0].snapped.positions);
  }
  if (options.json) {
    nlohmann::json out = {{"mesh", options.mesh},
                          {"refinement", measuring.spread ? "spread" : "uniform"},
                          {"refinement_levels", measuring.refined.levels},
                          {"measured_vertices", mesh.vertex_count()}};
    if (comparing) {
      out["a"] = measured_set_json(sets[0]);
      out["b"] = measured_set_json(sets[1]);
      out["mean_distance_a_to_b"] = a_to_b;
      out["mean_distance_b_to_a"] = b_to_a;
    } else {
      out.update(measured_set_json(sets[0]));
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
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
  if (comparing) {
    std::cout << "\nmean distance to the nearest particle of the other set: A -> B " << a_to_b << ", B -> A "
              << b_to_a << " (d_hex of A " << sets[0].quality.d_hex << ")\n";
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
                  "The refined mesh the points are measured on: auto (the mesh itself if every point lies on its "
                  "vertices, else spread's working mesh if they lie on it, else the fewest uniform midpoint rounds "
                  "that put every point within 0.5% of a spacing of a vertex), spread (that working mesh), or 0 to "
                  "8 uniform rounds")
      ->check(CLI::IsMember({"auto", "spread", "0", "1", "2", "3", "4", "5", "6", "7", "8"}))
      ->capture_default_str();
}

}  // namespace

void add_quality_command(CLI::App& app) {
  auto options = std::make_shared<QualityOptions>();
  CLI::App* quality = app.add_subcommand(
      "quality", "How evenly a particle file covers a mesh: nearest-neighbour distances, packing and covering radii, "
                 "energy (points are snapped to the nearest vertex of the mesh, refined where they lie between vertices)");
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
