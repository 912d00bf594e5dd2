#include "mesh/io/mesh_reader.hpp"

#include <cctype>

#include "common/user_error.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/io/mesh_file.hpp"

namespace meshparticles {

MeshFormat mesh_format_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".stl") return MeshFormat::stl;
  if (ext == ".vtk") return MeshFormat::vtk;
  if (ext == ".vtp") return MeshFormat::vtp;
  throw UserError(file.string() + ": unknown mesh format '" + ext + "' (use " + kMeshExtensions + ")");
}

PolygonSoup read_polygon_soup(std::span<const char> bytes, MeshFormat format, const std::string& label) {
  switch (format) {
    case MeshFormat::off:
      return read_off(bytes, label);
    case MeshFormat::obj:
      return read_obj(bytes, label);
    case MeshFormat::ply:
      return read_ply(bytes, label);
    case MeshFormat::stl:
      return read_stl(bytes, label);
    case MeshFormat::vtk:
      return read_vtk(bytes, label);
    case MeshFormat::vtp:
      return read_vtp(bytes, label);
  }
  throw UserError(label + ": unknown mesh format");
}

PolygonSoup read_polygon_soup(const std::filesystem::path& file) {
  const std::string label = file.string();
  const std::vector<char> bytes = read_mesh_file(file, label);
  return read_polygon_soup(bytes, mesh_format_of(file), label);
}

SurfaceMesh read_mesh(const std::filesystem::path& file, std::vector<std::string>& warnings,
                      const MeshReadOptions& options) {
  return build_checked_mesh(read_polygon_soup(file), file.string(), warnings, options);
}

}  // namespace meshparticles
