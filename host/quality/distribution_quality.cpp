#include "quality/distribution_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "particles/energy.hpp"

namespace meshparticles {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

std::vector<float> distance_to_nearest_particle(const DistanceStore& distances, std::span<const VertexId> positions) {
  std::vector<float> nearest(distances.vertex_count(), std::numeric_limits<float>::infinity());
  for (const VertexId p : positions) {
    distances.for_each_within(p, std::numeric_limits<float>::infinity(),
                              [&](VertexId v, float d) { nearest[v] = std::min(nearest[v], d); });
  }
  return nearest;
}

DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy) {
  return measure_quality(mesh, distances, positions, energy, distance_to_nearest_particle(distances, positions));
}

DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy,
                                    std::span<const float> to_nearest) {
  DistributionQuality quality;
  const std::size_t n = positions.size();
  quality.particles = n;
  quality.d_hex = n > 0 ? hexagonal_spacing(mesh.area(), n) : 0;

  std::vector<double> nearest(n, kInfinity);
  const double inv_two_sigma_sq = energy.inv_two_sigma_sq();
  std::vector<float> from_i(n);
  for (std::size_t i = 0; i < n; ++i) {
    distances.distances_from(positions[i], positions, from_i);
    for (std::size_t j = i + 1; j < n; ++j) {
      const double d = from_i[j];
      nearest[i] = std::min(nearest[i], d);
      nearest[j] = std::min(nearest[j], d);
      quality.energy += pair_weight(energy.potential, d, inv_two_sigma_sq);
    }
  }
  double sum = 0, sum_sq = 0, minimum = kInfinity;
  std::size_t counted = 0;
  for (const double d : nearest) {
    if (std::isinf(d)) continue;  // alone in its component
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
