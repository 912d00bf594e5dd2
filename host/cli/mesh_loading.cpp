#include "cli/mesh_loading.hpp"

#include <iostream>

#include "mesh/mesh_reader.hpp"

namespace meshparticles {

SurfaceMesh load_mesh(const std::filesystem::path& file, bool quiet) {
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_mesh(file, warnings);
  if (!quiet) {
    for (const auto& warning : warnings) std::cerr << "meshparticles: warning: " << warning << "\n";
  }
  return mesh;
}

}  // namespace meshparticles
