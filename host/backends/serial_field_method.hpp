#pragma once
// The field method in plain single-threaded C++ (`--backend serial-field`):
// the candidate rule, the schemes, collisions and the energy over a field F
// kept in fixed point. What differs between distance stores is how F is kept
// and where a weight comes from: SerialFieldBackend streams rows of a V x V
// weight table (the twin of the device's FieldBackend), LocalFieldBackend
// keeps F at the candidates from local balls. docs/ALGORITHM.md, "The field
// backend", is the contract.
#include <cstdint>
#include <span>
#include <vector>

#include "particles/particle_backend.hpp"

namespace meshparticles {

class SerialFieldMethod : public ParticleBackend {
 public:
  std::string device_name() const override { return kHostDevice; }
  void set_positions(std::span<const VertexId> positions) override;
  std::vector<VertexId> positions() override { return positions_; }
  IterationStats iterate(Scheme scheme, unsigned colors) override;
  double total_energy() override;

  // F from scratch at the current positions (for tests; --rebuild-every).
  virtual void rebuild_field() = 0;

 protected:
  SerialFieldMethod(const SurfaceMesh& mesh, std::size_t rebuild_every);

  // F(v) in field units (2^-40), for v a candidate of some particle.
  virtual std::int64_t field_at(VertexId v) const = 0;
  // The stored weight between u and v in field units: what F counts.
  virtual std::int64_t weight_units(VertexId u, VertexId v) const = 0;
  // After positions_ and occupancy_ say particle c moved from `from` to `to`.
  virtual void field_after_move(std::size_t c, VertexId from, VertexId to) = 0;
  // Before the moves of a sub-step to `targets` are committed (to fetch
  // what they will need at once).
  virtual void before_moves(std::span<const VertexId> /*targets*/) {}
  // Before the rule reads F at `vertex` and its one-ring (for a store that
  // makes F ready only when it is read).
  virtual void before_choice(VertexId /*vertex*/) {}

  const SurfaceMesh& mesh_;
  std::vector<std::uint32_t> occupancy_;  // particles on each vertex
  std::vector<VertexId> positions_;

 private:
  VertexId choice(std::size_t c, std::size_t stack_rank) const;
  void move(std::size_t c, VertexId target);
  std::size_t sequential_sweep();
  std::size_t synchronous_step(unsigned color, unsigned colors);

  std::size_t rebuild_every_;
  std::size_t iterations_ = 0;
};

}  // namespace meshparticles
