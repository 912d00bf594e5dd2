#include "quality/distribution_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <utility>

#include "common/progress.hpp"
#include "geodesics/local_distances.hpp"
#include "geodesics/solver_factory.hpp"
#include "particles/energy.hpp"

namespace meshparticles {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Fewer particles than this are measured without a progress line.
constexpr std::size_t kProgressParticles = 2000;

}  // namespace

std::vector<float> distance_to_nearest_particle(const SurfaceMesh& mesh, GeodesicMethod method,
                                                std::span<const VertexId> positions) {
  return distance_to_nearest_particle(*make_geodesic_solver(mesh, method), mesh, positions);
}

std::vector<float> distance_to_nearest_particle(const GeodesicSolver& solver, const SurfaceMesh& mesh,
                                                std::span<const VertexId> positions) {
  std::vector<double> distances(mesh.vertex_count());
  SolverScratch scratch;
  solver.solve(positions, distances, scratch);
  return std::vector<float>(distances.begin(), distances.end());
}

double geodesic_cover(const GeodesicSolver& solver, const SurfaceMesh& mesh, std::span<const VertexId> positions) {
  return largest_finite(distance_to_nearest_particle(solver, mesh, positions));
}

namespace {

// Calls pair(i, j, d) once for every pair of particles within the store's
// reach: all pairs i < j from a complete table (one batched query per
// particle), the pairs in each other's balls from a local store (only
// particles near each one are looked at, each pair from the particle on the
// smaller vertex: its distance costs two searches in the balls).
template <typename Pair>
void for_each_pair_within_reach(const DistanceStore& distances, std::span<const VertexId> positions, bool quiet,
                                Pair pair) {
  const std::size_t n = positions.size();
  const bool silent = quiet || n < kProgressParticles;
  if (std::isinf(distances.reach())) {
    ProgressLine progress("quality", n, silent);
    std::vector<float> from_i(n);
    for (std::size_t i = 0; i < n; ++i) {
      distances.distances_from(positions[i], positions, from_i);
      for (std::size_t j = i + 1; j < n; ++j) pair(i, j, double(from_i[j]));
      progress.update(i + 1);
    }
    progress.finish();
    return;
  }
  // Every particle's ball is read, by its own query and by its neighbours'.
  // Asked for a few at a time, they were solved on one thread: for 100k
  // particles on the 1M sphere this loop took 16.6 s, now 5.5 s for the
  // balls and 2.3 s for the loop. (A run holds them already.)
  if (const LocalDistances* balls = distances.local_balls()) balls->prefetch(positions);
  ProgressLine progress("quality", n, silent);
  std::vector<std::uint8_t> occupied(distances.vertex_count(), 0);
  std::vector<std::vector<std::size_t>> on_vertex(distances.vertex_count());  // particles by vertex
  for (std::size_t i = 0; i < n; ++i) {
    occupied[positions[i]] = 1;
    on_vertex[positions[i]].push_back(i);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const VertexId u = positions[i];
    distances.for_each_marked_within(u, distances.reach(), occupied, u, [&](VertexId v, float d) {
      for (const std::size_t j : on_vertex[v]) {
        if (v > u || j > i) pair(i, j, double(d));  // on one vertex: from the smaller index
      }
    });
    progress.update(i + 1);
  }
  progress.finish();
}

// Particles with no other within a local store's reach though their
// component holds others: each one's nearest is found by its own ball, and
// the pairs in that ball join the energy. The reach is sized for spacings
// on a surface, not along a line: 64 particles on a closed tube 10 long and
// 0.001 wide lie 0.16 apart, where 3 d_hex is 0.07, and every one was
// reported alone. The ball's radius is twice the largest distance from a
// vertex of the component to its nearest particle (where a particle's
// region meets another's, both are within that) and twice the component's
// longest edge, for the march's rounding: it holds the nearest other
// particle. `nearest` is lowered for them; returns the energy of the pairs
// found (each pair of two such particles once).
double reach_alone_particles(const SurfaceMesh& mesh, const LocalDistances& balls,
                             std::span<const VertexId> positions, std::span<const float> to_nearest,
                             const EnergyParams& energy, std::vector<double>& nearest) {
  const std::size_t n = positions.size();
  if (to_nearest.size() != mesh.vertex_count()) return 0;
  std::vector<std::size_t> in_component(mesh.component_count(), 0);
  for (const VertexId p : positions) ++in_component[mesh.component_of(p)];
  std::vector<std::uint8_t> alone(n, 0), searched(mesh.component_count(), 0);
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isinf(nearest[i]) || in_component[mesh.component_of(positions[i])] < 2) continue;
    alone[i] = 1;
    searched[mesh.component_of(positions[i])] = 1;
    any = true;
  }
  if (!any) return 0;
  std::vector<double> radius(mesh.component_count(), 0), longest_edge(mesh.component_count(), 0);
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    const std::uint32_t c = mesh.component_of(v);
    if (!searched[c]) continue;
    radius[c] = std::max(radius[c], double(to_nearest[v]));
    for (const VertexId w : mesh.one_ring(v)) {
      longest_edge[c] = std::max(longest_edge[c], distance(mesh.positions()[v], mesh.positions()[w]));
    }
  }
  std::vector<std::pair<VertexId, std::size_t>> on_vertex;  // (vertex, particle), by vertex
  for (std::size_t i = 0; i < n; ++i) on_vertex.emplace_back(positions[i], i);
  std::sort(on_vertex.begin(), on_vertex.end());
  const double inv_two_sigma_sq = energy.inv_two_sigma_sq();
  double added = 0;
  SolverScratch scratch;
  for (std::size_t i = 0; i < n; ++i) {
    if (!alone[i]) continue;
    const std::uint32_t c = mesh.component_of(positions[i]);
    const Ball ball = balls.solver().solve_ball(positions[i], 2 * radius[c] + 2 * longest_edge[c], scratch);
    for (std::size_t k = 0; k < ball.vertices.size(); ++k) {
      const VertexId v = ball.vertices[k];
      auto at = std::lower_bound(on_vertex.begin(), on_vertex.end(), std::pair<VertexId, std::size_t>(v, 0));
      for (; at != on_vertex.end() && at->first == v; ++at) {
        const std::size_t j = at->second;
        if (j == i) continue;
        const double d = double(ball.distances[k]);
        nearest[i] = std::min(nearest[i], d);
        if (alone[j]) nearest[j] = std::min(nearest[j], d);
        if (!alone[j] || i < j) added += pair_weight(energy.potential, d, inv_two_sigma_sq);
      }
    }
  }
  return added;
}

}  // namespace

DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy,
                                    std::span<const float> to_nearest, bool quiet) {
  DistributionQuality quality;
  const std::size_t n = positions.size();
  quality.particles = n;
  quality.d_hex = n > 0 ? hexagonal_spacing(mesh.area(), n) : 0;

  std::vector<double> nearest(n, kInfinity);
  const double inv_two_sigma_sq = energy.inv_two_sigma_sq();
  for_each_pair_within_reach(distances, positions, quiet, [&](std::size_t i, std::size_t j, double d) {
    nearest[i] = std::min(nearest[i], d);
    nearest[j] = std::min(nearest[j], d);
    quality.energy += pair_weight(energy.potential, d, inv_two_sigma_sq);
  });
  if (const LocalDistances* balls = distances.local_balls()) {
    quality.energy += reach_alone_particles(mesh, *balls, positions, to_nearest, energy, nearest);
  }
  double sum = 0, sum_sq = 0, minimum = kInfinity;
  std::size_t counted = 0;
  for (const double d : nearest) {
    if (std::isinf(d)) {  // alone in its component, or no other within reach
      ++quality.alone;
      continue;
    }
    sum += d;
    sum_sq += d * d;
    minimum = std::min(minimum, d);
    ++counted;
  }
  if (counted > 0) {
    const double mean = sum / double(counted);
    const double variance = std::max(0.0, sum_sq / double(counted) - mean * mean);
    quality.nn_min = minimum;
    quality.nn_mean = mean;
    quality.nn_std = std::sqrt(variance);
    if (mean > 0) quality.nn_cv = *quality.nn_std / mean;
    quality.rho = minimum / quality.d_hex;
  }

  if (n > 0) {
    double farthest = 0;  // the covering radius: the vertex farthest from every particle
    for (const float d : to_nearest) farthest = std::max(farthest, double(d));
    if (!std::isinf(farthest)) quality.cover = farthest / quality.d_hex;
  }

  std::unordered_set<VertexId> occupied;
  for (const VertexId p : positions) quality.stacked += occupied.insert(p).second ? 0 : 1;
  return quality;
}

}  // namespace meshparticles
