#pragma once
// The field method in plain C++ over the dense table, the twin of the
// device's FieldBackend: the same stored weights (a V x V table), the same
// fixed-point field over every vertex and the same float energies, bit for
// bit, given the same W. A move adds the row of its new vertex and
// subtracts the row of its old one.
#include "backends/backend_descriptor.hpp"
#include "backends/serial_field_method.hpp"
#include "geodesics/distance_table.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

class SerialFieldBackend final : public SerialFieldMethod {
 public:
  // rebuild_every: rebuild F from scratch every that many iterations (0: never).
  SerialFieldBackend(const SurfaceMesh& mesh, const DistanceTable& distances, const EnergyParams& energy,
                     WeightFormat weights, std::size_t rebuild_every);

  void rebuild_field() override;
  // For tests: F(v) of every vertex in field units (2^-40).
  const std::vector<std::int64_t>& field() const { return field_; }

 private:
  std::int64_t field_at(VertexId v) const override { return field_[v]; }
  std::int64_t weight_units(VertexId u, VertexId v) const override { return field_units(weight_row(u)[v]); }
  void field_after_move(std::size_t c, VertexId from, VertexId to) override;
  std::span<const float> weight_row(VertexId u) const {
    return {weights_.data() + std::size_t(u) * vertex_count_, vertex_count_};
  }

  std::size_t vertex_count_;
  std::vector<float> weights_;       // W, V x V, as stored (half values widened)
  std::vector<std::int64_t> field_;  // F(v) in field units
};

// The descriptor of `serial-field` (backend_table.hpp): this class on a
// dense table, LocalFieldBackend on local balls.
const BackendDescriptor& serial_field_backend();

}  // namespace meshparticles
