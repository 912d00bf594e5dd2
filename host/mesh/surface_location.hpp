#pragma once
// Where a point lies on a surface, in the two vocabularies the program uses:
// on a mesh it holds (a triangle of that SurfaceMesh, its weights and the
// point), and in a file's terms (a triangle's corners as the mesh file
// numbers its vertices, and their weights) for what is written or kept.
// Every point the program places is a SurfaceLocation of some mesh: a
// particle moving on the surface, a vertex of a refined mesh on the input
// (RefinedMesh::on_input), the template's particles in `correspond`. A
// vertex is one too (vertex_locations), since a SurfaceMesh has no vertex
// outside its triangles: its constructor refuses one, and the readers'
// checks drop such vertices first, keeping the others' file ids.
#include <array>
#include <cstddef>
#include <cstdint>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// A point of a triangle of a mesh: weights of its corners, non-negative and
// summing to 1, and the point they give.
struct SurfaceLocation {
  std::uint32_t triangle = 0;
  std::array<double, 3> weights{};
  Vec3 at;
};

// A point of a mesh's surface as the mesh file numbers its vertices: a
// triangle by its corners' input ids (SurfaceMesh::input_id) and their
// weights, non-negative and summing to 1.
struct InputLocation {
  std::array<VertexId, 3> corners{};
  std::array<double, 3> weights{};
  // The corner with the largest weight (ties: the first).
  VertexId heaviest_corner() const {
    std::size_t heaviest = 0;
    for (std::size_t k = 1; k < 3; ++k) {
      if (weights[k] > weights[heaviest]) heaviest = k;
    }
    return corners[heaviest];
  }
};

}  // namespace meshparticles
