#pragma once
// Keeps a moving point on the surface: from the triangle it was in, to the
// nearest point of the triangles around, step by step until none is nearer
// (a point that moved less than a triangle's size takes one or two steps).
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

class SurfaceWalk {
 public:
  explicit SurfaceWalk(const SurfaceMesh& mesh);
  // The point of the surface nearest to `target` reached by walking from
  // `from` (exact where the surface near `target` is within the triangles
  // the walk passes; a point moved less than the triangles' size).
  SurfaceLocation walk(std::uint32_t from, Vec3 target) const;
  // Vertex v as a point of its first triangle (every vertex is in one).
  SurfaceLocation at_vertex(VertexId v) const;
  // The first triangle holding vertex v.
  std::uint32_t first_triangle(VertexId v) const { return around_.around(v).front(); }
  // The triangles around each vertex.
  const VertexTriangles& triangles_around() const { return around_; }
  Vec3 normal(std::uint32_t triangle) const { return normals_[triangle]; }  // unit (zero if degenerate)
  // The unit direction of the triangle's first edge (zero if it has no length).
  Vec3 first_edge_direction(std::uint32_t triangle) const {
    const Triangle& c = mesh_.triangles()[triangle];
    const Vec3 edge = mesh_.positions()[c[1]] - mesh_.positions()[c[0]];
    return norm(edge) > 0 ? (1.0 / norm(edge)) * edge : Vec3{};
  }

 private:
  SurfaceLocation nearest_on(std::uint32_t triangle, Vec3 target) const;
  const SurfaceMesh& mesh_;
  VertexTriangles around_;
  std::vector<Vec3> normals_;
};

}  // namespace meshparticles
