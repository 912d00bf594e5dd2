#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

VertexTriangles vertex_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count) {
  VertexTriangles result;
  result.offsets.assign(vertex_count + 1, 0);
  for (const Triangle& t : triangles) {
    for (const VertexId v : t) ++result.offsets[v + 1];
  }
  for (std::size_t v = 0; v < vertex_count; ++v) result.offsets[v + 1] += result.offsets[v];
  result.triangles.resize(result.offsets[vertex_count]);
  std::vector<std::uint32_t> fill(result.offsets.begin(), result.offsets.end() - 1);
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (const VertexId v : triangles[t]) result.triangles[fill[v]++] = t;
  }
  return result;
}

}  // namespace meshparticles
