#include "batch/particle_count.hpp"

#include <algorithm>
#include <cmath>

namespace meshparticles {

std::size_t particles_for(const ParticleCount& count, double area, std::size_t vertices) {
  double n = count.value;
  switch (count.rule) {
    case ParticleCount::Rule::fixed: return std::size_t(count.value);
    case ParticleCount::Rule::spacing: n = 2.0 * area / (std::sqrt(3.0) * count.value * count.value); break;
    case ParticleCount::Rule::per_area: n = count.value * area; break;
  }
  // Compared as doubles first: a tiny spacing can ask for more than any size_t.
  return std::size_t(std::clamp(std::round(n), 1.0, double(std::max<std::size_t>(vertices, 1))));
}

}  // namespace meshparticles
