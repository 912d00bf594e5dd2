#pragma once
// The dense store: the V x V table of geodesic distances, float32,
// row-major, symmetric, zero diagonal, +inf between different components.
#include <cstdint>
#include <span>
#include <vector>

#include "geodesics/distance_store.hpp"
#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class DistanceTable final : public DistanceStore {
 public:
  explicit DistanceTable(std::size_t vertex_count)
      : vertex_count_(vertex_count), values_(vertex_count * vertex_count) {}

  std::size_t vertex_count() const override { return vertex_count_; }
  float distance(VertexId a, VertexId b) const override { return values_[std::size_t(a) * vertex_count_ + b]; }
  void distances_from(VertexId u, std::span<const VertexId> targets, std::span<float> out) const override;
  void for_each_marked_within(VertexId u, float radius, std::span<const std::uint8_t> marked, VertexId first,
                              const std::function<void(VertexId, float)>& visit) const override;
  const DistanceTable* dense_table() const override { return this; }

  float operator()(VertexId a, VertexId b) const { return distance(a, b); }
  std::span<const float> row(VertexId v) const { return {values_.data() + std::size_t(v) * vertex_count_, vertex_count_}; }
  std::span<float> row(VertexId v) { return {values_.data() + std::size_t(v) * vertex_count_, vertex_count_}; }
  std::span<const float> values() const { return values_; }
  std::span<float> values() { return values_; }
  std::uint64_t byte_size() const { return values_.size() * sizeof(float); }

 private:
  std::size_t vertex_count_;
  std::vector<float> values_;
};

// One source per task on `threads` threads (0: all cores), with a progress
// line on stderr unless quiet. The two one-sided solutions of each pair are
// averaged: d(u,v) and d(v,u) err independently, and their mean is the
// better estimate of the one true distance.
DistanceTable compute_all_pairs(const SurfaceMesh& mesh, GeodesicMethod method, unsigned threads, bool quiet);

// Makes a table symmetric in place by averaging mirrored entries (blocked,
// so both halves are read cache-line by cache-line).
void symmetrize_by_averaging(DistanceTable& table);

}  // namespace meshparticles
