#include "mesh/mesh_reader.hpp"

#include <fstream>

// OpenMesh wants its IO header before the mesh type.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/IO/reader/OFFReader.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "common/user_error.hpp"
#include "mesh/mesh_checks.hpp"

namespace meshparticles {

namespace {

using OpenMeshPoly = OpenMesh::PolyMesh_ArrayKernelT<>;

// Receives what OpenMesh's format readers parse and records it verbatim,
// instead of letting OpenMesh's own importer drop or duplicate faces it
// cannot add. Vertices still go into the (otherwise unused) OpenMesh mesh so
// the handles the readers hold stay valid.
class RecordingImporter : public OpenMesh::IO::ImporterT<OpenMeshPoly> {
 public:
  RecordingImporter(OpenMeshPoly& scratch, PolygonSoup& soup, bool announces_counts,
                    const std::istream* watched_input)
      : ImporterT<OpenMeshPoly>(scratch),
        soup_(soup),
        announces_counts_(announces_counts),
        watched_input_(watched_input) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    record_vertex({p[0], p[1], p[2]});
    return ImporterT::add_vertex(p);
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    record_vertex({p[0], p[1], p[2]});
    return ImporterT::add_vertex(p);
  }
  // The PLY reader adds a vertex first and sets its point afterwards.
  OpenMesh::VertexHandle add_vertex() override {
    record_vertex({});
    return ImporterT::add_vertex();
  }
  void set_point(OpenMesh::VertexHandle handle, const OpenMesh::Vec3f& p) override {
    soup_.vertices.at(std::size_t(handle.idx())) = {p[0], p[1], p[2]};
    ImporterT::set_point(handle, p);
  }
  OpenMesh::FaceHandle add_face(const OpenMesh::IO::BaseImporter::VHandles& handles) override {
    if (input_failed() && !soup_.first_unreadable_face) soup_.first_unreadable_face = soup_.faces.size();
    std::vector<long long> face;
    face.reserve(handles.size());
    for (const auto& h : handles) face.push_back(h.idx());
    soup_.faces.push_back(std::move(face));
    return OpenMesh::FaceHandle();  // no face in the scratch mesh: nothing to attach to
  }
  void reserve(unsigned int vertices, unsigned int edges, unsigned int faces) override {
    // OBJ and STL readers call reserve with guesses, not counts from a header.
    if (announces_counts_) {
      soup_.declared_vertices = vertices;
      soup_.declared_faces = faces;
    }
    ImporterT::reserve(vertices, edges, faces);
  }
  size_t n_faces() const override { return soup_.faces.size(); }

 private:
  bool input_failed() const { return watched_input_ != nullptr && watched_input_->fail(); }
  void record_vertex(const Vec3& p) {
    if (input_failed() && !soup_.first_unreadable_vertex) soup_.first_unreadable_vertex = soup_.vertices.size();
    soup_.vertices.push_back(p);
  }

  PolygonSoup& soup_;
  bool announces_counts_;
  const std::istream* watched_input_;
};

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// OpenMesh reports parse trouble on its own error stream; our one-line
// messages replace it, so it is muted while a file is read.
class MutedOpenMeshErrors {
 public:
  MutedOpenMeshErrors() { omerr().disable(); omlog().disable(); }
  ~MutedOpenMeshErrors() { omerr().enable(); omlog().enable(); }
};

}  // namespace

PolygonSoup read_polygon_soup(const std::filesystem::path& file) {
  const std::string label = file.string();
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw UserError(label + ": no such file");
  if (std::filesystem::is_directory(file, error)) throw UserError(label + ": is a directory, not a mesh file");
  if (!std::ifstream(file)) throw UserError(label + ": cannot be read (permission denied?)");

  const std::string ext = lowercase_extension(file);
  if (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") {
    throw UserError(label + ": unknown mesh format '" + ext + "' (use .off, .obj, .ply or .stl)");
  }

  PolygonSoup soup;
  OpenMeshPoly scratch;
  OpenMesh::IO::Options options;
  bool parsed = false;
  MutedOpenMeshErrors muted;
  if (ext == ".off") {
    // OpenMesh's OFF reader keeps going after its stream fails (a truncated
    // file, "nan"), handing on stale values. Reading from our own stream lets
    // the importer see the failure; can_u_read first sets up the reader's
    // view of the header (binary, normals, colours) as IOManager would.
    std::ifstream input(file, std::ios::binary);
    RecordingImporter importer(scratch, soup, true, &input);
    auto& reader = OpenMesh::IO::OFFReader();
    parsed = reader.can_u_read(file.string()) && reader.read(input, importer, options);
  } else {
    RecordingImporter importer(scratch, soup, ext == ".ply", nullptr);
    parsed = OpenMesh::IO::IOManager().read(file.string(), importer, options);
  }
  if (!parsed) throw UserError(label + ": not a readable " + ext.substr(1) + " file (malformed content)");
  return soup;
}

SurfaceMesh read_mesh(const std::filesystem::path& file, std::vector<std::string>& warnings) {
  return build_checked_mesh(read_polygon_soup(file), file.string(), warnings);
}

}  // namespace meshparticles
