#pragma once
// The pipeline's first step: a mesh file (or the default sphere) read and
// checked, its warnings on stderr, and vertex ids given by the user (input
// ids) turned into surface vertices.
#include <filesystem>
#include <span>
#include <string>

#include "mesh/mesh_checks.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Reads and checks a mesh, printing the reader's warnings on stderr unless
// quiet. `read.strict` refuses non-manifold input and repeated triangles.
SurfaceMesh load_mesh(const std::filesystem::path& file, bool quiet = false, const MeshReadOptions& read = {});
// The same from `bytes` read from `file` (mesh/io/mesh_file.hpp), for a
// caller that hashes the bytes it parses.
SurfaceMesh load_mesh(std::span<const char> bytes, const std::filesystem::path& file, bool quiet = false,
                      const MeshReadOptions& read = {});

// With `path` empty: the committed sphere when run from the repository, else
// the same sphere from the built-in generator, so default jobs run anywhere;
// `path` then names what was loaded. Otherwise load_mesh(path).
SurfaceMesh load_mesh_or_default(std::string& path, bool quiet = false, const MeshReadOptions& read = {});

// The surface vertex that had `input_id` in the file, for an option such as
// --source; throws UserError naming `option` when there is none.
VertexId surface_vertex_for_option(const SurfaceMesh& mesh, std::size_t input_id, const std::string& option);

}  // namespace meshparticles
