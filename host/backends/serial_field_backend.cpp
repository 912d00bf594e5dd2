#include "backends/serial_field_backend.hpp"

#include "backends/host_collisions.hpp"
#include "common/user_error.hpp"
#include "geodesics/memory_guard.hpp"
#include "particles/energy.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

SerialFieldBackend::SerialFieldBackend(const SurfaceMesh& mesh, const DistanceTable& distances,
                                       const EnergyParams& energy, WeightFormat weights, std::size_t rebuild_every)
    : mesh_(mesh), vertex_count_(mesh.vertex_count()), rebuild_every_(rebuild_every) {
  check_table_fits(vertex_count_, sizeof(float), usable_host_memory_bytes(), "weight table", "host memory");
  // In float, as the device computes it (particle_energy.h).
  const float inv_two_sigma_sq = float(energy.inv_two_sigma_sq());
  const auto& d = distances.values();
  weights_.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    weights_[i] = stored_weight(weights, pair_weight_float(energy.potential, d[i], inv_two_sigma_sq));
  }
  field_.assign(vertex_count_, 0);
  occupancy_.assign(vertex_count_, 0);
}

void SerialFieldBackend::rebuild_field() {
  std::fill(field_.begin(), field_.end(), 0);
  std::fill(occupancy_.begin(), occupancy_.end(), 0);
  for (const VertexId p : positions_) {
    const auto row = weight_row(p);
    for (std::size_t v = 0; v < vertex_count_; ++v) field_[v] += field_units(row[v]);
    ++occupancy_[p];
  }
}

void SerialFieldBackend::set_positions(std::span<const VertexId> positions) {
  if (positions.size() > kMaxFieldParticles) {
    throw UserError("the field backends take at most " + std::to_string(kMaxFieldParticles) +
                    " particles: the 64-bit field would overflow");
  }
  positions_.assign(positions.begin(), positions.end());
  iterations_ = 0;
  rebuild_field();
}

// The rule of kernels/field_update.cl, on the current F.
VertexId SerialFieldBackend::choice(std::size_t c, std::size_t stack_rank) const {
  const VertexId here = positions_[c];
  const auto ring = mesh_.one_ring(here);
  const auto own_row = weight_row(here);
  std::vector<double> energies(ring.size() + 1);
  std::vector<bool> occupied(energies.size());
  for (std::size_t j = 0; j < energies.size(); ++j) {
    const VertexId v = j == 0 ? here : ring[j - 1];
    energies[j] = field_energy(field_[v] - field_units(own_row[v]));
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

void SerialFieldBackend::move(std::size_t c, VertexId target) {
  const VertexId from = positions_[c];
  const auto old_row = weight_row(from), new_row = weight_row(target);
  for (std::size_t v = 0; v < vertex_count_; ++v) field_[v] += field_units(new_row[v]) - field_units(old_row[v]);
  --occupancy_[from];
  ++occupancy_[target];
  positions_[c] = target;
}

std::size_t SerialFieldBackend::sequential_sweep() {
  std::size_t moved = 0;
  for (std::size_t c = 0; c < positions_.size(); ++c) {
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
std::size_t SerialFieldBackend::synchronous_step(unsigned color, unsigned colors) {
  std::vector<std::size_t> movers;
  std::vector<VertexId> targets;
  for (std::size_t c = color; c < positions_.size(); c += colors) {
    std::size_t stack_rank = 0;
    if (occupancy_[positions_[c]] > 1) {
      for (std::size_t i = 0; i < c; ++i) stack_rank += positions_[i] == positions_[c];
    }
    const VertexId target = choice(c, stack_rank);
    if (target != positions_[c]) {
      movers.push_back(c);
      targets.push_back(target);
    }
  }
  return commit_in_index_order(targets, vertex_count_, [&](std::size_t k) { move(movers[k], targets[k]); });
}

IterationStats SerialFieldBackend::iterate(Scheme scheme, unsigned colors) {
  IterationStats stats;
  if (scheme == Scheme::sequential) {
    stats.moved = sequential_sweep();
  } else {
    const unsigned groups = sub_steps(scheme, colors);
    for (unsigned color = 0; color < groups; ++color) stats.moved += synchronous_step(color, groups);
  }
  if (rebuild_every_ > 0 && ++iterations_ % rebuild_every_ == 0) rebuild_field();
  stats.energy = total_energy();
  return stats;
}

double SerialFieldBackend::total_energy() {
  double sum = 0;
  for (const VertexId p : positions_) sum += double(field_[p] - field_units(weight_row(p)[p]));
  return sum / (2.0 * double(kFieldUnitsPerWeight));
}

const BackendDescriptor& serial_field_backend() {
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = "serial-field";
    d.summary = "the field method in plain single-threaded C++, every scheme; the twin of field";
    d.field_method = true;
    d.default_scheme = Scheme::sequential;
    d.paper_row = PaperRow::cpu;
    d.extra_host_bytes_per_entry = sizeof(float);  // W beside the distance table
    d.make_host = [](const BackendInputs& inputs) -> std::unique_ptr<ParticleBackend> {
      return std::make_unique<SerialFieldBackend>(inputs.mesh, dense_table_for(inputs.distances, "serial-field"),
                                                  inputs.energy, inputs.weights, inputs.rebuild_every);
    };
    return d;
  }();
  return descriptor;
}

}  // namespace meshparticles
