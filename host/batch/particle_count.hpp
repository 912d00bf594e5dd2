#pragma once
// How many particles each mesh of a batch gets: a fixed n, or n from a
// density, so that shapes of different sizes are covered alike (the same
// spacing between neighbours on a small shape and on a large one).
#include <cstddef>

namespace meshparticles {

struct ParticleCount {
  enum class Rule {
    fixed,     // n itself (more than the mesh's vertices is refused, as by `run`)
    spacing,   // the hexagonal spacing d_hex H, in mesh units: n = round(2A / (sqrt(3) H^2))
    per_area,  // particles per unit of area D: n = round(D A)
  };
  Rule rule = Rule::fixed;
  double value = 1024;
};

// n for a mesh of `area` and `vertices`. The density rules round to the
// nearest whole number and clamp to [1, vertices]: every mesh gets a run.
std::size_t particles_for(const ParticleCount& count, double area, std::size_t vertices);

}  // namespace meshparticles
