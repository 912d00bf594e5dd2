#pragma once
// Per vertex, the sum of its triangles' normals weighted by their areas (not
// unit: a vertex of degenerate triangles only has none). What "the way a
// vertex faces" means where one triangle of a scan is flipped or a sliver:
// its neighbours outweigh it.
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

std::vector<Vec3> vertex_normals(const SurfaceMesh& mesh);

}  // namespace meshparticles
