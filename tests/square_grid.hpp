#pragma once
// A flat test surface whose geodesics are straight lines.
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles::testing {

// The unit square in z = 0, a grid of `cells` x `cells` squares, each cut in two.
inline SurfaceMesh square_grid(int cells) {
  std::vector<Vec3> positions;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) positions.push_back({double(i) / cells, double(j) / cells, 0});
  }
  std::vector<Triangle> triangles;
  const auto at = [&](int i, int j) { return VertexId(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

}  // namespace meshparticles::testing
