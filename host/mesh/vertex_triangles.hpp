#pragma once
// The triangles around each vertex, in CSR form, each list in increasing
// triangle order: the vertex fans the mesh checks look at, and the triangles
// of an edge that fast marching's unfoldings cross (those of one end that
// hold the other).
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct VertexTriangles {
  std::vector<std::uint32_t> offsets;    // per vertex, and one past the last
  std::vector<std::uint32_t> triangles;  // three entries per triangle
  std::span<const std::uint32_t> around(VertexId v) const {
    return {triangles.data() + offsets[v], offsets[v + 1] - offsets[v]};
  }
};

VertexTriangles vertex_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count);

}  // namespace meshparticles
