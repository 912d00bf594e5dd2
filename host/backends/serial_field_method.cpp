#include "backends/serial_field_method.hpp"

#include "backends/host_collisions.hpp"
#include "particles/energy.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

SerialFieldMethod::SerialFieldMethod(const SurfaceMesh& mesh, std::size_t rebuild_every)
    : mesh_(mesh), occupancy_(mesh.vertex_count(), 0), rebuild_every_(rebuild_every) {}

void SerialFieldMethod::set_positions(std::span<const VertexId> positions) {
  check_field_particle_count(positions.size());
  positions_.assign(positions.begin(), positions.end());
  std::fill(occupancy_.begin(), occupancy_.end(), 0);
  for (const VertexId p : positions_) ++occupancy_[p];
  iterations_ = 0;
  rebuild_field();
}

// The rule of kernels/field_update.cl, on the current F.
VertexId SerialFieldMethod::choice(std::size_t c, std::size_t stack_rank) const {
  const VertexId here = positions_[c];
  const auto ring = mesh_.one_ring(here);
  std::vector<double> energies(ring.size() + 1);
  std::vector<bool> occupied(energies.size());
  for (std::size_t j = 0; j < energies.size(); ++j) {
    const VertexId v = j == 0 ? here : ring[j - 1];
    energies[j] = field_energy(field_at(v) - weight_units(here, v));
    occupied[j] = occupancy_[v] > (j == 0 ? 1u : 0u);
  }
  if (!occupied[0]) {
    for (std::size_t j = 1; j < energies.size(); ++j) {
      if (occupied[j]) energies[j] = kBlocked;
    }
  }
  const std::size_t best = candidate_of_rank(energies, stack_rank);
  return best == 0 ? here : ring[best - 1];
}

void SerialFieldMethod::move(std::size_t c, VertexId target) {
  const VertexId from = positions_[c];
  --occupancy_[from];
  ++occupancy_[target];
  positions_[c] = target;
  field_after_move(c, from, target);
}

std::size_t SerialFieldMethod::sequential_sweep() {
  std::size_t moved = 0;
  for (std::size_t c = 0; c < positions_.size(); ++c) {
    before_choice(positions_[c]);
    const VertexId target = choice(c, 0);
    if (target != positions_[c]) {
      move(c, target);
      ++moved;
    }
  }
  return moved;
}

// As SerialBackend::synchronous_step: one snapshot, stack ranks, the
// smallest index wins a contested vertex; F follows the committed moves.
std::size_t SerialFieldMethod::synchronous_step(unsigned color, unsigned colors) {
  std::vector<std::size_t> movers;
  std::vector<VertexId> targets;
  for (std::size_t c = color; c < positions_.size(); c += colors) {
    std::size_t stack_rank = 0;
    if (occupancy_[positions_[c]] > 1) {
      for (std::size_t i = 0; i < c; ++i) stack_rank += positions_[i] == positions_[c];
    }
    before_choice(positions_[c]);
    const VertexId target = choice(c, stack_rank);
    if (target != positions_[c]) {
      movers.push_back(c);
      targets.push_back(target);
    }
  }
  before_moves(targets);
  return commit_in_index_order(targets, mesh_.vertex_count(), [&](std::size_t k) { move(movers[k], targets[k]); });
}

IterationStats SerialFieldMethod::iterate(Scheme scheme, unsigned colors) {
  IterationStats stats;
  stats.moved = host_iteration_moves(
      scheme, colors, [&] { return sequential_sweep(); },
      [&](unsigned color, unsigned groups) { return synchronous_step(color, groups); });
  if (rebuild_every_ > 0 && ++iterations_ % rebuild_every_ == 0) rebuild_field();
  stats.energy = total_energy();
  return stats;
}

// Half the sum over particles of the energy each feels where it is.
double SerialFieldMethod::total_energy() {
  FieldEnergySum sum;
  for (const VertexId p : positions_) sum.add(field_at(p) - weight_units(p, p));
  return sum.pair_energy();
}

}  // namespace meshparticles
