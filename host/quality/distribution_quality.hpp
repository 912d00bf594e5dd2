#pragma once
// How evenly a particle set covers a surface, measured geodesically through
// the distance store (docs/QUALITY.md): nearest-neighbour distances,
// normalized packing and covering radii, energy, stacked particles. Their
// JSON and text forms are in reports/quality_report.hpp.
#include <optional>
#include <span>
#include <vector>

#include "geodesics/distance_store.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

struct DistributionQuality {
  std::size_t particles = 0;
  // Nearest-neighbour geodesic distance of each particle (another particle on
  // its vertex: 0; none in its component: left out). Absent with < 2 particles.
  std::optional<double> nn_min, nn_mean, nn_std, nn_cv;
  double d_hex = 0;             // sqrt(2A / (sqrt(3) n)), the hexagonal spacing
  std::optional<double> rho;    // nn_min / d_hex: the normalized packing radius
  std::optional<double> cover;  // max over vertices of the distance to the nearest particle, / d_hex;
                                // absent when a component holds no particle
  double energy = 0;            // sum_{i<j} w(d(p_i, p_j)) at the given sigma, in double
  std::size_t stacked = 0;      // particles on a vertex a lower-index particle occupies
};

// The geodesic distance from every vertex to its nearest particle (+inf in a
// component without particles): the covering radius is its maximum.
std::vector<float> distance_to_nearest_particle(const DistanceStore& distances, std::span<const VertexId> positions);

// `to_nearest`: distance_to_nearest_particle of these positions, for a
// caller that also writes it out; the shorter form computes it.
DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy,
                                    std::span<const float> to_nearest);
DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy);

}  // namespace meshparticles
