#pragma once
// The reference: single-threaded plain C++, energies accumulated in double,
// every scheme. It is the oracle every kernel is tested against.
#include "backends/backend_descriptor.hpp"
#include "geodesics/distance_store.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

class SerialBackend : public ParticleBackend {
 public:
  SerialBackend(const SurfaceMesh& mesh, const DistanceStore& distances, const EnergyParams& energy);

  std::string device_name() const override { return kHostDevice; }
  void set_positions(std::span<const VertexId> positions) override;
  std::vector<VertexId> positions() override { return positions_; }
  IterationStats iterate(Scheme scheme, unsigned colors) override;
  double total_energy() override;

  // E_c(v) for every candidate v of particle c (its vertex, then its
  // one-ring), with the other particles at `positions`; +inf for a blocked
  // candidate (occupied, while c is alone on its vertex).
  std::vector<double> candidate_energies(std::size_t c, std::span<const VertexId> positions) const;

 private:
  std::size_t sequential_sweep();
  std::size_t synchronous_step(unsigned color, unsigned colors);
  VertexId candidate_vertex(VertexId here, std::size_t candidate) const;

  const SurfaceMesh& mesh_;
  const DistanceStore& distances_;
  EnergyParams energy_;
  std::vector<VertexId> positions_;
  mutable std::vector<float> to_particles_;  // scratch: one candidate's distances to every particle
};

// The reference's descriptor (backend_table.hpp).
const BackendDescriptor& serial_backend();

}  // namespace meshparticles
