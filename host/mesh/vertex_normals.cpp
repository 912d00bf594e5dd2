#include "mesh/vertex_normals.hpp"

namespace meshparticles {

std::vector<Vec3> vertex_normals(const SurfaceMesh& mesh) {
  const auto& positions = mesh.positions();
  std::vector<Vec3> normals(mesh.vertex_count());
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 n = cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
    for (const VertexId v : t) normals[v] = normals[v] + n;
  }
  return normals;
}

}  // namespace meshparticles
