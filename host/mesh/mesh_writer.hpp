#pragma once
#include <filesystem>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Writes `mesh` through OpenMesh in the format its extension names, atomically.
void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& file);

}  // namespace meshparticles
