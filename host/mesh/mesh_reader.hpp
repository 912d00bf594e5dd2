#pragma once
// Mesh input: OFF, OBJ, PLY and STL parsed by OpenMesh into a polygon soup,
// then checked (mesh_checks) and handed on as a SurfaceMesh.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/polygon_soup.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Reads and checks `file`. Throws UserError("FILE: problem") on anything the
// program cannot use; appends one line per tolerated oddity to `warnings`.
SurfaceMesh read_mesh(const std::filesystem::path& file, std::vector<std::string>& warnings);

// The parsing step alone: OpenMesh's reader, recording what it was given.
PolygonSoup read_polygon_soup(const std::filesystem::path& file);

}  // namespace meshparticles
