#pragma once
// Mesh input: OFF, OBJ, PLY, STL and VTK (legacy and XML) read by our own strict readers
// (format_readers) into a polygon soup, then checked (mesh_checks) and handed
// on as a SurfaceMesh. Why not a library: docs/MESHES.md.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh_checks.hpp"
#include "mesh/polygon_soup.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// A format the program reads: the file extension that names it (lower case,
// with its dot) and its reader. The formats are one table in mesh_reader.cpp.
struct MeshFormat {
  const char* extension;
  PolygonSoup (*read)(std::span<const char> bytes, const std::string& label);
};

// The extensions of the formats read, for messages: ".off, .obj, ...".
std::string mesh_extensions();

// The format a file name's extension (any case) names; throws UserError for
// any other extension.
const MeshFormat& mesh_format_of(const std::filesystem::path& file);

// Reads and checks `file`. Throws UserError("FILE: problem") on anything the
// program cannot use; appends one line per tolerated oddity to `warnings`.
SurfaceMesh read_mesh(const std::filesystem::path& file, std::vector<std::string>& warnings,
                      const MeshReadOptions& options = {});
// The same from `bytes` already read from `file` (read_mesh_file): what a
// caller that also hashes them needs, so the digest is of what was parsed.
SurfaceMesh read_mesh(std::span<const char> bytes, const std::filesystem::path& file,
                      std::vector<std::string>& warnings, const MeshReadOptions& options = {});

// The parsing step alone, from a file (regular files up to
// kMaxMeshFileBytes) or from bytes in memory; `label` starts every message.
PolygonSoup read_polygon_soup(const std::filesystem::path& file);
PolygonSoup read_polygon_soup(std::span<const char> bytes, const MeshFormat& format, const std::string& label);

}  // namespace meshparticles
