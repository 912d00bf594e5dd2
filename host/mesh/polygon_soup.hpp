#pragma once
// A mesh file exactly as it was written, before any checking: vertex
// positions, faces as raw index lists, and the counts a header promised.
#include <cstddef>
#include <optional>
#include <vector>

#include "mesh/vec3.hpp"

namespace meshparticles {

struct PolygonSoup {
  std::vector<Vec3> vertices;
  std::vector<std::vector<long long>> faces;
  std::optional<std::size_t> declared_vertices;  // from formats with a header (OFF, PLY)
  std::optional<std::size_t> declared_faces;
  // The first vertex / face the reader added after its input had already
  // failed (a malformed number, or the file ended): what follows is stale.
  std::optional<std::size_t> first_unreadable_vertex;
  std::optional<std::size_t> first_unreadable_face;
};

}  // namespace meshparticles
