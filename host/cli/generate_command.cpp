#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "common/user_error.hpp"
#include "common/atomic_file.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"

namespace meshparticles {

namespace {

struct GenerateOptions {
  std::vector<std::string> names;
  std::string out_dir = "meshes";
  std::optional<std::size_t> vertices;
};

void run_generate(const GenerateOptions& options) {
  if (options.vertices && options.names.empty()) {
    throw UserError("--vertices needs the meshes to make at that size: sphere, atrium or both");
  }
  const std::vector<std::string>& names = options.names.empty() ? generated_mesh_names() : options.names;
  create_directory_for(options.out_dir, "output directory");
  check_writable_directory(options.out_dir);
  for (const std::string& name : names) {
    const SurfaceMesh mesh = options.vertices ? generate_mesh_at(name, *options.vertices) : generate_mesh(name);
    // At another size the file says so: NAME_V.off, never a committed mesh's name.
    const std::string stem = options.vertices ? name + "_" + std::to_string(mesh.vertex_count()) : name;
    const auto file = std::filesystem::path(options.out_dir) / (stem + ".off");
    write_mesh(mesh, file);
    std::cerr << "wrote " << file.string() << " (" << mesh.vertex_count() << " vertices, "
              << mesh.triangle_count() << " triangles)\n";
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
                          "benchmarks on large meshes)");
  generate->callback([options] { run_generate(*options); });
}

}  // namespace meshparticles
