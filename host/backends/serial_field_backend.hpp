#pragma once
// The field method in plain single-threaded C++ (`--backend serial-field`),
// the twin of FieldBackend: the same stored weights, the same fixed-point
// field and the same float energies, bit for bit, given the same W. Every
// scheme; a sequential move updates F at once, so later particles see it.
#include "backends/backend_descriptor.hpp"
#include "geodesics/distance_table.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

class SerialFieldBackend : public ParticleBackend {
 public:
  // rebuild_every: rebuild F from scratch every that many iterations (0: never).
  SerialFieldBackend(const SurfaceMesh& mesh, const DistanceTable& distances, const EnergyParams& energy,
                     WeightFormat weights, std::size_t rebuild_every);

  std::string device_name() const override { return "serial"; }
  void set_positions(std::span<const VertexId> positions) override;
  std::vector<VertexId> positions() override { return positions_; }
  IterationStats iterate(Scheme scheme, unsigned colors) override;
  double total_energy() override;

  // For tests: F(v) in field units (2^-40), and a rebuild from the positions.
  const std::vector<std::int64_t>& field() const { return field_; }
  void rebuild_field();

 private:
  std::span<const float> weight_row(VertexId u) const { return {weights_.data() + std::size_t(u) * vertex_count_, vertex_count_}; }
  VertexId choice(std::size_t c, std::size_t stack_rank) const;
  void move(std::size_t c, VertexId target);
  std::size_t sequential_sweep();
  std::size_t synchronous_step(unsigned color, unsigned colors);

  const SurfaceMesh& mesh_;
  std::size_t vertex_count_;
  std::size_t rebuild_every_;
  std::size_t iterations_ = 0;
  std::vector<float> weights_;        // W, V x V, as stored (half values widened)
  std::vector<std::int64_t> field_;   // F(v) in field units
  std::vector<std::uint32_t> occupancy_;
  std::vector<VertexId> positions_;
};

// The field method's serial twin's descriptor (backend_table.hpp).
const BackendDescriptor& serial_field_backend();

}  // namespace meshparticles
