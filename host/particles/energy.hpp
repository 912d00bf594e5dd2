#pragma once
// The serial reference's copy of kernels/particle_energy.h: the same
// potential and candidate order, evaluated in double. Keep the two in step.
#include <cmath>
#include <cstddef>
#include <span>

#include "particles/particle_params.hpp"

namespace meshparticles {

// w(d); zero across components (d = +inf).
inline double pair_weight(Potential potential, double d, double inv_two_sigma_sq) {
  return std::exp(-distance_term(potential, d) * inv_two_sigma_sq);
}

// Candidate a comes before b: lower energy, then lower index (index 0 is the
// current vertex, the one-ring follows in increasing id).
inline bool ranks_before(double energy_a, std::size_t a, double energy_b, std::size_t b) {
  return energy_a < energy_b || (energy_a == energy_b && a < b);
}

// The energy recorded for a blocked candidate: one another particle sits on,
// seen by a particle alone on its vertex (see kernels/particle_energy.h).
inline constexpr double kBlocked = INFINITY;

// The index of the candidate of rank `rank` (0: the best), or 0 (stay) when
// there are fewer candidates or that one is blocked.
inline std::size_t candidate_of_rank(std::span<const double> energies, std::size_t rank) {
  if (rank >= energies.size()) return 0;
  for (std::size_t j = 0; j < energies.size(); ++j) {
    std::size_t before = 0;
    for (std::size_t i = 0; i < energies.size(); ++i) before += ranks_before(energies[i], i, energies[j], j);
    if (before == rank) return std::isinf(energies[j]) ? 0 : j;
  }
  return 0;
}

}  // namespace meshparticles
