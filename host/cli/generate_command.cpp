#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/random.hpp"
#include "common/user_error.hpp"
#include "fixtures/bent_body.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"
#include "options/number_options.hpp"

namespace meshparticles {

namespace {

struct GenerateOptions {
  std::vector<std::string> names;
  std::string out_dir = "meshes";
  std::optional<std::size_t> vertices;
  std::optional<std::size_t> population;
  std::string family = "atrium";
  std::uint64_t seed = 1;
};

// The size of each shape of a --population without --vertices: the committed atrium's.
constexpr std::size_t kPopulationVertices = 10000;

void write_generated(const SurfaceMesh& mesh, const std::filesystem::path& file) {
  write_mesh(mesh, file);
  std::cerr << "wrote " << file.string() << " (" << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
            << " triangles)\n";
}

nlohmann::json vec_json(Vec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json pose_truth(const ShapePose& pose) {
  return {{"rotation", {vec_json(pose.rotation[0]), vec_json(pose.rotation[1]), vec_json(pose.rotation[2])}},
          {"scale", pose.scale},
          {"translation", vec_json(pose.translation)}};
}

// population.json: what each ellipsoid shape is, so that a surface point's
// parameter (its true correspondence) can be worked out from where it lies.
nlohmann::json ellipsoid_truth(const std::string& file, const EllipsoidVariant& shape) {
  nlohmann::json truth = {{"mesh", file},
                          {"elongation", shape.elongation},
                          {"bump_height", shape.bump_height},
                          {"knob_height", shape.knob_height},
                          {"axes", vec_json(shape.axes)}};
  truth.update(pose_truth(shape.pose));
  return truth;
}

// population.json of the bent family: what each shape is, as for the
// ellipsoid families, and how to unbend a point to find its parameter.
nlohmann::json bent_truth(const std::string& file, const BentBody& shape) {
  nlohmann::json truth = {{"mesh", file},
                          {"axes", vec_json(shape.axes)},
                          {"waist_depth", shape.waist_depth},
                          {"bump_heights", shape.bump_heights},
                          {"bend_angle", shape.bend_angle},
                          {"bend_radius", shape.bend_radius},
                          {"bend_side", shape.bend_side}};
  truth.update(pose_truth(shape.pose));
  return truth;
}

nlohmann::json ellipsoid_population(const nlohmann::json& shapes, std::uint64_t seed, const std::string& family) {
  return {{"family", family},
          {"parameter", "u = normalize(diag(axes)^-1 x), x = rotation^T (world - translation) / scale"},
          {"surface", "x(u) = (1 + bump_height exp(-(1 - u.bump_direction) / bump_width) + knob_height exp(-(1 - "
                      "u.knob_direction) / knob_width)) diag(axes) u, each shape with its axes, bump_height and "
                      "knob_height"},
          {"bump_direction", vec_json(kEllipsoidBump.direction)},
          {"bump_width", kEllipsoidBump.width},
          {"knob_direction", vec_json(kEllipsoidKnob.direction)},
          {"knob_width", kEllipsoidKnob.width},
          {"seed", seed},
          {"shapes", shapes}};
}

nlohmann::json bent_population(const nlohmann::json& shapes, std::uint64_t seed, const std::string& family) {
  nlohmann::json bumps = nlohmann::json::array();
  for (const BentBodyBump& bump : kBentBodyBumps) bumps.push_back({{"direction", vec_json(bump.direction)}, {"width", bump.width}});
  return {{"family", family},
          {"parameter", "u = normalize(diag(axes)^-1 s), s = T (R - |q|, q_y, R atan2(q_z, -q_x)), q = T x - (R, 0, 0), "
                        "R = bend_radius, x = rotation^T (world - translation) / scale, T = diag(-1, -1, 1) where "
                        "bend_side is -1, else the identity"},
          {"surface", "x(u) = bend(s(u)), s(u) = (1 - waist_depth exp(-(u_z / waist_width)^2) + sum_k bump_heights[k] "
                      "exp(-(1 - u.bumps[k].direction) / bumps[k].width)) diag(axes) u, bend(s) = (R - (R - s_x) "
                      "cos(s_z / R), s_y, (R - s_x) sin(s_z / R)) where bend_side is 1, T bend(T s) where it is -1, each "
                      "shape with its axes, waist_depth, bump_heights, bend_radius (R = 2 axes_z / bend_angle) and "
                      "bend_side"},
          {"waist_width", kBentBodyWaistWidth},
          {"bumps", bumps},
          {"seed", seed},
          {"shapes", shapes}};
}

// Shape i from the i-th number of the seed's sequence: a population is fixed
// by its seed, and a longer one begins with the shorter.
void write_population(const GenerateOptions& options) {
  const std::filesystem::path out(options.out_dir);
  const std::size_t vertices = options.vertices.value_or(kPopulationVertices);
  SplitMix64 shape_seeds(options.seed);
  nlohmann::json shapes = nlohmann::json::array();
  for (std::size_t i = 0; i < *options.population; ++i) {
    char name[40];
    std::snprintf(name, sizeof name, "%s_%03zu.off", options.family.c_str(), i);
    if (options.family == "atrium") {
      write_generated(generate_atrium_variant(shape_seeds.next(), vertices), out / name);
    } else if (options.family == "bent" || options.family == "bent-either") {
      const BentBody shape = generate_bent_body(shape_seeds.next(), vertices,
                                                options.family == "bent" ? BendSides::one : BendSides::either);
      write_generated(shape.mesh, out / name);
      shapes.push_back(bent_truth(name, shape));
    } else {
      const EllipsoidFamily family = options.family == "radii" ? EllipsoidFamily::radii : EllipsoidFamily::knob;
      const EllipsoidVariant shape = generate_ellipsoid_variant(shape_seeds.next(), vertices, family);
      write_generated(shape.mesh, out / name);
      shapes.push_back(ellipsoid_truth(name, shape));
    }
  }
  if (options.family != "atrium") {
    const bool bent = options.family == "bent" || options.family == "bent-either";
    const nlohmann::json truth = bent ? bent_population(shapes, options.seed, options.family)
                                      : ellipsoid_population(shapes, options.seed, options.family);
    write_file_atomically(out / "population.json", [&](std::ostream& stream) { stream << json_text(truth, 2) << "\n"; });
    std::cerr << "wrote " << (out / "population.json").string() << " (each shape's parameters and pose)\n";
  }
}

void run_generate(const GenerateOptions& options) {
  if (options.population && !options.names.empty()) {
    throw UserError("--population writes a population of --family shapes: give no NAMES");
  }
  if (options.vertices && options.names.empty() && !options.population) {
    throw UserError("--vertices needs the meshes to make at that size: sphere, atrium or both");
  }
  create_directory_for(options.out_dir, "output directory");
  check_writable_directory(options.out_dir);
  if (options.population) {
    write_population(options);
    return;
  }
  for (const std::string& name : options.names.empty() ? generated_mesh_names() : options.names) {
    const SurfaceMesh mesh = options.vertices ? generate_mesh_at(name, *options.vertices) : generate_mesh(name);
    // At another size the file says so: NAME_V.off, never a committed mesh's name.
    const std::string stem = options.vertices ? name + "_" + std::to_string(mesh.vertex_count()) : name;
    write_generated(mesh, std::filesystem::path(options.out_dir) / (stem + ".off"));
  }
}

}  // namespace

void add_generate_command(CLI::App& app) {
  auto options = std::make_shared<GenerateOptions>();
  CLI::App* generate = app.add_subcommand("generate", "Regenerate the project's test meshes, bit for bit");
  generate->add_option("names", options->names, "Meshes to write (default: all)")
      ->check(CLI::IsMember(generated_mesh_names()));
  generate->add_option("--out-dir", options->out_dir, "Directory to write NAME.off into")->capture_default_str();
  add_whole_number_option(*generate, "--vertices", options->vertices, kLargeMeshRange,
                          "Make sphere or atrium at about this many vertices instead (as NAME_V.off; for "
                          "benchmarks on large meshes); with --population, each shape's size (default " +
                              std::to_string(kPopulationVertices) + ")");
  add_whole_number_option(*generate, "--population", options->population, kPopulationRange,
                          "Write a population of this many shapes instead, FAMILY_000.off, ..., from --seed");
  generate->add_option("--family", options->family,
                       "With --population: atrium (each with its own size, body and bulges; for batch benchmarks), "
                       "ellipsoid (two true modes, each meshed on its own and posed at random, with the true "
                       "correspondence in population.json; for correspond), radii (as ellipsoid, each radius "
                       "within 20% of 1.25, 1, 0.8 so their order swaps, and a knob of its own height, at times "
                       "none: shapes whose principal axes cannot pose them), bent (elongated bodies bent 30 to "
                       "90 degrees, with a waist and three small bumps, posed at random: each shape all but its "
                       "own half turn, only the bumps telling the two poses apart) or bent-either (as bent, each "
                       "bent to either side: a mode that goes both ways around a nearly straight mean)")
      ->check(CLI::IsMember({"atrium", "ellipsoid", "radii", "bent", "bent-either"}))
      ->capture_default_str();
  add_whole_number_option(*generate, "--seed", options->seed, kSeedRange, "Seed of the --population");
  generate->callback([options] { run_generate(*options); });
}

}  // namespace meshparticles
