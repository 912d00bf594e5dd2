#pragma once
// The potentials of the paper's energy, one entry each: what the command
// line, the reports, the sigma rule and the kernels know of a potential.
// A third potential is one entry in potential_table(), its term in
// distance_term (particle_params.hpp: a switch that does not compile
// without it) and its branch in kernels/particle_energy.h.
#include <string>
#include <vector>

#include "particles/particle_params.hpp"

namespace meshparticles {

struct PotentialSpec {
  Potential potential;
  std::string name;    // --potential's value and report.json's
  std::string weight;  // w(d), for --help
  // The value of POTENTIAL_GAUSS, kernels/particle_energy.h's switch.
  long long kernel_define;
  // The default sigma from the hexagonal spacing d_hex, chosen by
  // measurement (docs/ALGORITHM.md).
  double (*default_sigma)(double d_hex);
};

// Every potential, in the order help texts list them.
const std::vector<PotentialSpec>& potential_table();

const PotentialSpec& potential_spec(Potential potential);

std::vector<std::string> potential_names();

// --potential's default, and RunRequest's.
inline constexpr Potential kDefaultPotential = Potential::exp;

}  // namespace meshparticles
