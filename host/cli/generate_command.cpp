#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "common/atomic_file.hpp"
#include "common/random.hpp"
#include "common/user_error.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"

namespace meshparticles {

namespace {

struct GenerateOptions {
  std::vector<std::string> names;
  std::string out_dir = "meshes";
  std::optional<std::size_t> vertices;
  std::optional<std::size_t> population;
  std::uint64_t seed = 1;
};

// The size of each shape of a --population without --vertices: the committed atrium's.
constexpr std::size_t kPopulationVertices = 10000;

void write_generated(const SurfaceMesh& mesh, const std::filesystem::path& file) {
  write_mesh(mesh, file);
  std::cerr << "wrote " << file.string() << " (" << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
            << " triangles)\n";
}

void run_generate(const GenerateOptions& options) {
  if (options.population && !options.names.empty()) {
    throw UserError("--population writes atrium-like shapes: give no NAMES");
  }
  if (options.vertices && options.names.empty() && !options.population) {
    throw UserError("--vertices needs the meshes to make at that size: sphere, atrium or both");
  }
  create_directory_for(options.out_dir, "output directory");
  check_writable_directory(options.out_dir);
  if (options.population) {
    // Shape i from the i-th number of the seed's sequence: a population is
    // fixed by its seed, and a longer one begins with the shorter.
    SplitMix64 shape_seeds(options.seed);
    for (std::size_t i = 0; i < *options.population; ++i) {
      const SurfaceMesh mesh = generate_atrium_variant(shape_seeds.next(), options.vertices.value_or(kPopulationVertices));
      char name[40];
      std::snprintf(name, sizeof name, "atrium_%03zu.off", i);
      write_generated(mesh, std::filesystem::path(options.out_dir) / name);
    }
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
                          "Write this many atrium-like shapes instead, atrium_000.off, ..., each with its own "
                          "size, body and bulges from --seed (for batch benchmarks)");
  add_whole_number_option(*generate, "--seed", options->seed, kSeedRange, "Seed of the --population");
  generate->callback([options] { run_generate(*options); });
}

}  // namespace meshparticles
