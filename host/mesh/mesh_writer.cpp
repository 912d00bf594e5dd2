#include "mesh/mesh_writer.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "common/atomic_file.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
}  // namespace

void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& file) {
  OpenMesh::TriMesh_ArrayKernelT<DoubleTraits> out;
  for (const Vec3& p : mesh.positions()) out.add_vertex({p.x, p.y, p.z});
  for (const Triangle& t : mesh.triangles()) {
    out.add_face(OpenMesh::VertexHandle(int(t[0])), OpenMesh::VertexHandle(int(t[1])),
                 OpenMesh::VertexHandle(int(t[2])));
  }
  // Through our own atomic writer: OpenMesh's file variant reports no failed
  // write (a full disk left a truncated file and "success"). Nine
  // significant digits hold a float exactly: regenerated files compare equal.
  write_file_atomically(
      file,
      [&](std::ostream& stream) {
        if (!OpenMesh::IO::write_mesh(out, stream, file.extension().string(), OpenMesh::IO::Options::Default, 9)) {
          throw UserError(file.string() + ": cannot write mesh (format " + file.extension().string() + ")");
        }
      },
      true);
}

}  // namespace meshparticles
