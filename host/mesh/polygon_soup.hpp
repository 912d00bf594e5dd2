#pragma once
// A mesh file exactly as it was written, before any checking: vertex
// positions and faces as raw index lists (zero-based, not yet range-checked).
// Faces are stored one after another in one array, so a million small faces
// cost two allocations, not a million.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "mesh/vec3.hpp"

namespace meshparticles {

struct PolygonSoup {
  std::vector<Vec3> vertices;
  // Face f is face_vertices[face_starts[f] .. face_starts[f + 1]).
  std::vector<long long> face_vertices;
  std::vector<std::size_t> face_starts{0};
  // What the reader read past, e.g. lines after the faces a header declares.
  std::vector<std::string> warnings;

  std::size_t face_count() const { return face_starts.size() - 1; }
  std::span<const long long> face(std::size_t f) const {
    return {face_vertices.data() + face_starts[f], face_starts[f + 1] - face_starts[f]};
  }
  // A face is built by appending its indices to face_vertices, then closed.
  void close_face() { face_starts.push_back(face_vertices.size()); }
  void add_triangle(long long a, long long b, long long c) {
    face_vertices.insert(face_vertices.end(), {a, b, c});
    close_face();
  }
};

}  // namespace meshparticles
