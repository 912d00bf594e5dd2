#pragma once
// The one way the particle system and its metrics read geodesic distances
// between vertices: point queries, batched queries from one source, and the
// marked vertices within a radius. Two stores stand behind it: the dense
// V x V table (distance_table.hpp) and local balls computed on demand
// (local_distances.hpp), for meshes whose table would not fit. (Distances
// from every vertex to a set of sources - starts, covering radii - come from
// a solver directly: geodesic_solver.hpp.)
#include <cstdint>
#include <functional>
#include <limits>
#include <span>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

class DistanceTable;
class LocalDistances;

class DistanceStore {
 public:
  virtual ~DistanceStore() = default;

  virtual std::size_t vertex_count() const = 0;

  // d(u, v), symmetric; +inf between components and beyond reach().
  virtual float distance(VertexId u, VertexId v) const = 0;

  // out[k] = d(u, targets[k]) for every k: one call per source in the hot
  // loops (a candidate's energy reads its distance to every particle).
  virtual void distances_from(VertexId u, std::span<const VertexId> targets, std::span<float> out) const = 0;

  // visit(v, d(u, v)) for every vertex v >= first that `marked` marks
  // (marked[v] != 0) with d(u, v) <= radius, u itself included, in
  // increasing v: the few vertices of interest near u (the particles, for
  // nearest neighbours) without paying for all the others. `first` = u
  // gives each pair of marked vertices once, from the smaller.
  virtual void for_each_marked_within(VertexId u, float radius, std::span<const std::uint8_t> marked, VertexId first,
                                      const std::function<void(VertexId, float)>& visit) const = 0;

  // How far the store knows distances: +inf for a complete table.
  virtual float reach() const { return std::numeric_limits<float>::infinity(); }

  // The complete table, for the consumers that stream whole rows (the
  // device kernels, the field's weight table); nullptr when there is none.
  virtual const DistanceTable* dense_table() const { return nullptr; }
  // The local balls, for the consumers that read them directly (the field
  // backends keep F from them); nullptr for another store.
  virtual const LocalDistances* local_balls() const { return nullptr; }
};

}  // namespace meshparticles
