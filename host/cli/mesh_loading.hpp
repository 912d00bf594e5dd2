#pragma once
#include <filesystem>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Reads a mesh for a command, printing the reader's warnings on stderr.
SurfaceMesh load_mesh(const std::filesystem::path& file, bool quiet = false);

}  // namespace meshparticles
