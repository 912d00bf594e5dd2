#pragma once
// One strict, streaming reader per mesh format, each over a file already in
// memory (mesh_reader reads the file; the fuzz harness passes its input).
// Each throws UserError("LABEL: problem"), naming the line in text formats,
// and never reads or allocates past what the bytes it is given can hold.
// What each accepts is written at the top of its .cpp and in docs/MESHES.md.
#include <span>
#include <string>

#include "mesh/polygon_soup.hpp"

namespace meshparticles {

// A new format: its reader declared here, and its row in mesh_reader.cpp's table.
PolygonSoup read_off(std::span<const char> bytes, const std::string& label);
PolygonSoup read_ply(std::span<const char> bytes, const std::string& label);
PolygonSoup read_obj(std::span<const char> bytes, const std::string& label);
PolygonSoup read_stl(std::span<const char> bytes, const std::string& label);
PolygonSoup read_vtk(std::span<const char> bytes, const std::string& label);
PolygonSoup read_vtp(std::span<const char> bytes, const std::string& label);

}  // namespace meshparticles
