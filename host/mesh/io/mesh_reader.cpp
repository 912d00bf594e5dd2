#include "mesh/io/mesh_reader.hpp"

#include <array>
#include <cctype>

#include "common/user_error.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/io/mesh_file.hpp"

namespace meshparticles {

namespace {

// Every format read, in the order messages list them. A new format is its
// reader's file and one row here.
constexpr std::array kMeshFormats{
    MeshFormat{".off", read_off}, MeshFormat{".obj", read_obj}, MeshFormat{".ply", read_ply},
    MeshFormat{".stl", read_stl}, MeshFormat{".vtk", read_vtk}, MeshFormat{".vtp", read_vtp},
};

}  // namespace

std::string mesh_extensions() {
  std::string extensions;
  for (const MeshFormat& format : kMeshFormats) {
    extensions += (extensions.empty() ? "" : ", ") + std::string(format.extension);
  }
  return extensions;
}

const MeshFormat& mesh_format_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const MeshFormat& format : kMeshFormats) {
    if (ext == format.extension) return format;
  }
  throw UserError(file.string() + ": unknown mesh format '" + ext + "' (use " + mesh_extensions() + ")");
}

PolygonSoup read_polygon_soup(std::span<const char> bytes, const MeshFormat& format, const std::string& label) {
  return format.read(bytes, label);
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

SurfaceMesh read_mesh(std::span<const char> bytes, const std::filesystem::path& file,
                      std::vector<std::string>& warnings, const MeshReadOptions& options) {
  const std::string label = file.string();
  return build_checked_mesh(read_polygon_soup(bytes, mesh_format_of(file), label), label, warnings, options);
}

}  // namespace meshparticles
