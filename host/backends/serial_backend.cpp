#include "backends/serial_backend.hpp"

#include "backends/host_collisions.hpp"
#include "particles/energy.hpp"

namespace meshparticles {

SerialBackend::SerialBackend(const SurfaceMesh& mesh, const DistanceStore& distances, const EnergyParams& energy)
    : mesh_(mesh), distances_(distances), energy_(energy) {}

void SerialBackend::set_positions(std::span<const VertexId> positions) {
  positions_.assign(positions.begin(), positions.end());
}

VertexId SerialBackend::candidate_vertex(VertexId here, std::size_t candidate) const {
  return candidate == 0 ? here : mesh_.one_ring(here)[candidate - 1];
}

std::vector<double> SerialBackend::candidate_energies(std::size_t c, std::span<const VertexId> positions) const {
  const double inv_two_sigma_sq = energy_.inv_two_sigma_sq();
  const VertexId here = positions[c];
  std::vector<double> energies(mesh_.valence(here) + 1, 0.0);
  std::vector<bool> occupied(energies.size(), false);
  to_particles_.resize(positions.size());
  for (std::size_t j = 0; j < energies.size(); ++j) {
    const VertexId v = candidate_vertex(here, j);
    distances_.distances_from(v, positions, to_particles_);
    double energy = 0;
    bool taken = false;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (i == c) continue;
      energy += pair_weight(energy_.potential, to_particles_[i], inv_two_sigma_sq);
      taken |= positions[i] == v;
    }
    energies[j] = energy;
    occupied[j] = taken;
  }
  if (!occupied[0]) {  // alone on its vertex: occupied neighbours are blocked
    for (std::size_t j = 1; j < energies.size(); ++j) {
      if (occupied[j]) energies[j] = kBlocked;
    }
  }
  return energies;
}

// The paper's CPU loop: each particle sees the moves made before it.
std::size_t SerialBackend::sequential_sweep() {
  std::size_t moved = 0;
  for (std::size_t c = 0; c < positions_.size(); ++c) {
    const VertexId here = positions_[c];
    const VertexId target = candidate_vertex(here, candidate_of_rank(candidate_energies(c, positions_), 0));
    if (target != here) {
      positions_[c] = target;
      ++moved;
    }
  }
  return moved;
}

// The particles of one colour decide from one snapshot; the k-th particle
// stacked on a vertex (by index, over all particles) takes its k-th best
// candidate. When several
// choose the same (free) vertex, the smallest index moves there and the
// others stay.
std::size_t SerialBackend::synchronous_step(unsigned color, unsigned colors) {
  const std::vector<VertexId> snapshot = positions_;
  std::vector<std::size_t> movers;
  std::vector<VertexId> targets;
  for (std::size_t c = color; c < snapshot.size(); c += colors) {
    std::size_t stack_rank = 0;
    for (std::size_t i = 0; i < c; ++i) stack_rank += snapshot[i] == snapshot[c];
    const VertexId target = candidate_vertex(snapshot[c], candidate_of_rank(candidate_energies(c, snapshot), stack_rank));
    if (target != snapshot[c]) {
      movers.push_back(c);
      targets.push_back(target);
    }
  }
  return commit_in_index_order(targets, mesh_.vertex_count(),
                               [&](std::size_t k) { positions_[movers[k]] = targets[k]; });
}

IterationStats SerialBackend::iterate(Scheme scheme, unsigned colors) {
  IterationStats stats;
  stats.moved = host_iteration_moves(
      scheme, colors, [&] { return sequential_sweep(); },
      [&](unsigned color, unsigned groups) { return synchronous_step(color, groups); });
  stats.energy = total_energy();
  return stats;
}

double SerialBackend::total_energy() {
  const double inv_two_sigma_sq = energy_.inv_two_sigma_sq();
  double total = 0;
  to_particles_.resize(positions_.size());
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    distances_.distances_from(positions_[i], positions_, to_particles_);
    for (std::size_t j = i + 1; j < positions_.size(); ++j) {
      total += pair_weight(energy_.potential, to_particles_[j], inv_two_sigma_sq);
    }
  }
  return total;
}

const BackendDescriptor& serial_backend() {
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = "serial";
    d.summary = "the reference: plain single-threaded C++ in double, every scheme; the oracle";
    d.default_scheme = Scheme::sequential;
    d.paper_row = PaperRow::cpu;
    d.make_host = [](const BackendInputs& inputs) -> std::unique_ptr<ParticleBackend> {
      return std::make_unique<SerialBackend>(inputs.mesh, inputs.distances, inputs.energy);
    };
    return d;
  }();
  return descriptor;
}

}  // namespace meshparticles
