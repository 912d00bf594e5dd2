#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"

namespace meshparticles {

namespace {

struct GenerateOptions {
  std::vector<std::string> names;
  std::string out_dir = "meshes";
};

void run_generate(const GenerateOptions& options) {
  const std::vector<std::string>& names = options.names.empty() ? generated_mesh_names() : options.names;
  create_directory_for(options.out_dir, "output directory");
  check_writable_directory(options.out_dir);
  for (const std::string& name : names) {
    const SurfaceMesh mesh = generate_mesh(name);
    const auto file = std::filesystem::path(options.out_dir) / (name + ".off");
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
  generate->callback([options] { run_generate(*options); });
}

}  // namespace meshparticles
