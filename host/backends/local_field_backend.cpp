#include "backends/local_field_backend.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "common/worker_threads.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

LocalFieldBackend::LocalFieldBackend(const SurfaceMesh& mesh, const LocalDistances& balls, const EnergyParams& energy,
                                     WeightFormat weights, std::size_t rebuild_every)
    : SerialFieldMethod(mesh, rebuild_every),
      balls_(balls),
      potential_(energy.potential),
      inv_two_sigma_sq_(float(energy.inv_two_sigma_sq())),
      weights_(weights),
      field_(mesh.vertex_count(), 0),
      candidates_(mesh, balls),
      ring_units_(mesh.ring_neighbors().size(), kNotYet),
      spread_weights_(mesh.vertex_count()),
      units_at_zero_(units_of_distance(0.0f)) {}

float LocalFieldBackend::weight_of_distance(float d) const {
  if (std::isinf(d)) return 0;  // beyond reach: the weight the store cuts off
  return stored_weight(weights_, pair_weight_float(potential_, d, inv_two_sigma_sq_));
}

std::int64_t LocalFieldBackend::units_of_distance(float d) const { return field_units(weight_of_distance(d)); }

std::int64_t LocalFieldBackend::units_between(const Ball& from_u, VertexId u, const Ball& from_v, VertexId v) const {
  return units_of_distance(LocalDistances::symmetric_distance(from_u, u, from_v, v));
}

float LocalFieldBackend::weight_of_pair(float from_u_to_v, float from_v_to_u) const {
  return weight_of_distance(LocalDistances::symmetric_mean(from_u_to_v, from_v_to_u));  // 0 if either is +inf
}

// u is a particle's vertex and v one of its candidates: u itself (at
// distance 0 in its own ball) or in its one-ring, and both held.
std::int64_t LocalFieldBackend::weight_units(VertexId u, VertexId v) const {
  if (u == v) return units_at_zero_;
  const auto ring = mesh_.one_ring(u);
  const auto at = std::find(ring.begin(), ring.end(), v);
  if (at == ring.end()) return units_between(*candidates_.ball(u), u, *candidates_.ball(v), v);
  std::int64_t& units = ring_units_[mesh_.ring_offsets()[u] + std::size_t(at - ring.begin())];
  if (units == kNotYet) units = units_between(*candidates_.ball(u), u, *candidates_.ball(v), v);
  return units;
}

// Every particle's vertex is a candidate (its index 0), so its ball is held.
std::int64_t LocalFieldBackend::field_from_scratch(VertexId x) const {
  const Ball& from_x = *candidates_.ball(x);
  std::int64_t sum = 0;
  for_each_distance_to(
      x, from_x.vertices.size(),
      [&](std::size_t k) { return occupancy_[from_x.vertices[k]] > 0 ? candidates_.ball(from_x.vertices[k]) : nullptr; },
      [&](std::size_t k, float back) {
        sum += std::int64_t(occupancy_[from_x.vertices[k]]) * field_units(weight_of_pair(from_x.distances[k], back));
      });
  return sum;
}

void LocalFieldBackend::learn_spread_weights(VertexId u) {
  const Ball& from_u = *candidates_.ball(u);
  std::vector<float>& weights = spread_weights_[u];
  if (weights.empty()) weights.assign(from_u.vertices.size(), kUnknown);
  for_each_distance_to(
      u, from_u.vertices.size(),
      [&](std::size_t k) { return weights[k] == kUnknown ? candidates_.ball(from_u.vertices[k]) : nullptr; },
      [&](std::size_t k, float back) { weights[k] = weight_of_pair(from_u.distances[k], back); });
}

void LocalFieldBackend::spread_weight(VertexId from, int delta) {
  // from is a candidate of the moving particle either side of the move, so
  // its ball is held; a candidate not ready yet gets its whole F when it is.
  learn_spread_weights(from);
  const Ball& from_ball = *candidates_.ball(from);
  const std::vector<float>& weights = spread_weights_[from];
  for (std::size_t k = 0; k < from_ball.vertices.size(); ++k) {
    const VertexId x = from_ball.vertices[k];
    if (candidates_.ball(x)) field_[x] += delta * field_units(weights[k]);
  }
  if (occupancy_[from] == 0) std::vector<float>().swap(spread_weights_[from]);
}

void LocalFieldBackend::make_ready(VertexId v) {
  if (candidates_.ball(v) || !candidates_.is_candidate(v)) return;
  candidates_.hold(v);
  field_[v] = field_from_scratch(v);  // reads the balls of the particles' vertices, all ready
}

void LocalFieldBackend::before_choice(VertexId vertex) {
  make_ready(vertex);
  for (const VertexId v : mesh_.one_ring(vertex)) make_ready(v);
}

// The particle already stands at `to` in positions_ and occupancy_: its
// weight moves from `from` to `to` at every candidate, then its own
// candidates follow it (new ones see the particle at `to`): the balls of
// the new ones are asked of the store's helpers, those of the old let go.
void LocalFieldBackend::field_after_move(std::size_t /*c*/, VertexId from, VertexId to) {
  spread_weight(from, -1);
  spread_weight(to, +1);
  std::vector<VertexId> arrivals, departures;
  candidates_.arrive(to, arrivals);
  balls_.request(arrivals);
  candidates_.depart(from, departures);
  for (const VertexId v : departures) candidates_.release(v);
}

void LocalFieldBackend::before_moves(std::span<const VertexId> targets) {
  std::vector<VertexId> needed;
  for (const VertexId t : targets) {
    needed.push_back(t);
    for (const VertexId v : mesh_.one_ring(t)) needed.push_back(v);
  }
  balls_.prefetch(needed);
}

void LocalFieldBackend::rebuild_field() {
  candidates_.clear_counts();
  candidates_.release_all();
  std::vector<VertexId> wanted, arrivals;
  for (const VertexId p : positions_) {
    candidates_.arrive(p, arrivals);
    wanted.push_back(p);
    for (const VertexId v : mesh_.one_ring(p)) wanted.push_back(v);
  }
  balls_.prefetch(wanted);  // on all cores, before the sums read them one by one
  const std::vector<VertexId> all = candidates_.list();
  for (const VertexId x : all) candidates_.hold(x);
  // F is the sum of every occupied vertex's weights, spread. Learning those
  // weights is the costly part (a search in each candidate's ball) and
  // writes only the vertex's own list: they are shared out among the
  // store's threads (on a big mesh this took seconds on one core).
  for (auto& weights : spread_weights_) std::vector<float>().swap(weights);
  std::vector<VertexId> occupied;
  for (VertexId v = 0; v < occupancy_.size(); ++v) {
    if (occupancy_[v] > 0) occupied.push_back(v);
  }
  const auto threads = unsigned(std::min<std::size_t>(balls_.threads(), 1 + occupied.size() / 128));
  const auto learn_every = [&](unsigned first) {
    for (std::size_t k = first; k < occupied.size(); k += threads) learn_spread_weights(occupied[k]);
  };
  WorkerThreads helpers(threads - 1, [&](unsigned t) { learn_every(t + 1); });
  for (unsigned t = helpers.started() + 1; t < threads; ++t) learn_every(t);  // shares whose thread did not start
  learn_every(0);
  helpers.join();
  for (const VertexId x : all) field_[x] = 0;
  for (const VertexId u : occupied) spread_weight(u, int(occupancy_[u]));
}

}  // namespace meshparticles
