#pragma once
// The compact, read-only triangle mesh that everything after mesh input works
// on: plain arrays, one-ring adjacency in CSR form (no maximum valence), and
// the statistics the particle system and reports need. The readers hand over
// a polygon soup; the numeric code never sees a half-edge structure.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "mesh/vec3.hpp"

namespace meshparticles {

using VertexId = std::uint32_t;
using Triangle = std::array<VertexId, 3>;

class SurfaceMesh {
 public:
  // `triangles` must index `positions`, no triangle twice (the reader's checks
  // guarantee it). They need not be manifold: an edge in three triangles is
  // interior (boundary means one), and separate fans may share a vertex. `input_ids[v]` is the id vertex v had in
  // the input file (empty: the identity), out of `input_vertex_count` vertices
  // the file had (0: as many as here).
  // Every vertex lies in a triangle (std::invalid_argument otherwise): a
  // vertex is a point of the surface, so every point a run places or writes
  // is a triangle and weights (SurfaceLocation). The readers' checks drop
  // vertices no triangle uses, keeping the others' input ids.
  SurfaceMesh(std::vector<Vec3> positions, std::vector<Triangle> triangles,
              std::vector<VertexId> input_ids = {}, std::size_t input_vertex_count = 0);

  std::size_t vertex_count() const { return positions_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }
  const std::vector<Vec3>& positions() const { return positions_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }

  // Neighbours of v sorted by id, and the CSR arrays behind them (for devices).
  std::span<const VertexId> one_ring(VertexId v) const {
    return {ring_neighbors_.data() + ring_offsets_[v], ring_offsets_[v + 1] - ring_offsets_[v]};
  }
  std::size_t valence(VertexId v) const { return ring_offsets_[v + 1] - ring_offsets_[v]; }
  std::size_t max_valence() const;
  const std::vector<std::uint32_t>& ring_offsets() const { return ring_offsets_; }
  const std::vector<VertexId>& ring_neighbors() const { return ring_neighbors_; }
  std::size_t edge_count() const { return ring_neighbors_.size() / 2; }

  double area() const { return area_; }
  double mean_edge_length() const { return mean_edge_length_; }

  std::size_t component_count() const { return component_count_; }
  std::uint32_t component_of(VertexId v) const { return component_[v]; }

  bool is_boundary(VertexId v) const { return boundary_[v] != 0; }
  std::size_t boundary_vertex_count() const;

  VertexId input_id(VertexId v) const { return input_ids_.empty() ? v : input_ids_[v]; }
  std::size_t input_vertex_count() const { return input_vertex_count_; }
  // The vertex that had `input_id` in the file; nothing for a dropped vertex.
  std::optional<VertexId> vertex_of_input_id(std::size_t input_id) const;

 private:
  std::vector<Vec3> positions_;
  std::vector<Triangle> triangles_;
  std::vector<VertexId> input_ids_;
  std::vector<std::uint32_t> ring_offsets_;
  std::vector<VertexId> ring_neighbors_;
  std::vector<std::uint32_t> component_;
  std::vector<std::uint8_t> boundary_;
  std::size_t component_count_ = 0;
  std::size_t input_vertex_count_ = 0;
  double area_ = 0;
  double mean_edge_length_ = 0;
};

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c);

// The longest edge of any triangle of `mesh` (0 without triangles): how far
// a point of a triangle can be from each of its corners.
double longest_edge(const SurfaceMesh& mesh);

}  // namespace meshparticles
