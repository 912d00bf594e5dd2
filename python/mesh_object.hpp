#pragma once
// meshparticles.Mesh: a checked surface (mesh/surface_mesh.hpp) shared by
// every call that takes it, and where it came from for reports.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles::python {

struct Mesh {
  std::shared_ptr<const SurfaceMesh> surface;
  std::string label;                         // the file's path, or "<arrays>": names the mesh in messages
  std::optional<std::filesystem::path> file;  // read from this file (report.json records its SHA-256)
  std::vector<std::string> warnings;          // the reader's and the checks' warnings, one line each
};

}  // namespace meshparticles::python
