#include "pipeline/mesh_input.hpp"

#include <iostream>

#include "common/user_error.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "fixtures/mesh_generator.hpp"

namespace meshparticles {

namespace {

void print_warnings(const std::vector<std::string>& warnings, bool quiet) {
  if (quiet) return;
  for (const auto& warning : warnings) std::cerr << "meshparticles: warning: " << warning << "\n";
}

}  // namespace

SurfaceMesh load_mesh(const std::filesystem::path& file, bool quiet, const MeshReadOptions& read) {
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_mesh(file, warnings, read);
  print_warnings(warnings, quiet);
  return mesh;
}

SurfaceMesh load_mesh(std::span<const char> bytes, const std::filesystem::path& file, bool quiet,
                      const MeshReadOptions& read) {
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_mesh(bytes, file, warnings, read);
  print_warnings(warnings, quiet);
  return mesh;
}

SurfaceMesh load_mesh_or_default(std::string& path, bool quiet, const MeshReadOptions& read) {
  const char* const committed_sphere = "meshes/sphere.off";
  if (path.empty() && !std::filesystem::exists(committed_sphere)) {
    path = "built-in:sphere";
    return generate_mesh("sphere");
  }
  if (path.empty()) path = committed_sphere;
  return load_mesh(path, quiet, read);
}

VertexId surface_vertex_for_option(const SurfaceMesh& mesh, std::size_t input_id, const std::string& option) {
  const auto vertex = mesh.vertex_of_input_id(input_id);
  if (!vertex) {
    throw UserError(option + " " + std::to_string(input_id) + " is not a vertex of the surface (the mesh has " +
                    std::to_string(mesh.input_vertex_count()) + " vertices; unreferenced ones are dropped)");
  }
  return *vertex;
}

}  // namespace meshparticles
