#pragma once
// How evenly a particle set covers a surface, measured geodesically through
// the distance store (docs/QUALITY.md): nearest-neighbour distances,
// normalized packing and covering radii, energy, stacked particles. Their
// JSON and text forms are in reports/quality_report.hpp.
#include <optional>
#include <span>
#include <vector>

#include "geodesics/distance_store.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

struct DistributionQuality {
  std::size_t particles = 0;
  // Nearest-neighbour geodesic distance of each particle (another particle on
  // its vertex: 0). One with no other within a local store's cutoff whose
  // component holds others is given its nearest by a ball of its own (a thin
  // tube's spacing is far more than the cutoff); a particle alone in its
  // component is left out and counted in `alone`. Absent when every
  // particle is alone.
  std::optional<double> nn_min, nn_mean, nn_std, nn_cv;
  std::size_t alone = 0;
  double d_hex = 0;             // sqrt(2A / (sqrt(3) n)), the hexagonal spacing
  std::optional<double> rho;    // nn_min / d_hex: the normalized packing radius
  std::optional<double> cover;  // max over vertices of the distance to the nearest particle, / d_hex;
                                // absent when a component holds no particle
  double energy = 0;            // sum_{i<j} w(d(p_i, p_j)) at the given sigma, in double, over the pairs
                                // within the store's reach, and those in the balls of particles it left
                                // without a neighbour
  std::size_t stacked = 0;      // particles on a vertex a lower-index particle occupies
};

// The geodesic distance from every vertex to its nearest particle (+inf in a
// component without particles), by one solve from all particles at once:
// the covering radius is its maximum.
std::vector<float> distance_to_nearest_particle(const SurfaceMesh& mesh, GeodesicMethod method,
                                                std::span<const VertexId> positions);
// The same with a solver already built for `mesh` (building one sets up
// every triangle's stencils: a third of a solve on a 100k-vertex mesh).
std::vector<float> distance_to_nearest_particle(const GeodesicSolver& solver, const SurfaceMesh& mesh,
                                                std::span<const VertexId> positions);

// The geodesic covering radius of `positions`: the largest finite distance
// from a vertex to its nearest particle (a component without particles
// left out), by one solve of `solver`, built for `mesh`.
double geodesic_cover(const GeodesicSolver& solver, const SurfaceMesh& mesh, std::span<const VertexId> positions);

// `to_nearest`: distance_to_nearest_particle of these positions (the
// covering radius comes from it). Nearest neighbours and the energy come
// from `distances`: all pairs from a complete table, the pairs within reach
// from a local store (which first solves every particle's ball it does not
// hold, on all cores). Unless `quiet`, a progress line counts the particles.
DistributionQuality measure_quality(const SurfaceMesh& mesh, const DistanceStore& distances,
                                    std::span<const VertexId> positions, const EnergyParams& energy,
                                    std::span<const float> to_nearest, bool quiet);

}  // namespace meshparticles
