#pragma once
// Whether a sigma given by the user makes a meaningful run. The energy is a
// sum of w(d) = exp(-x) with x = d / (2 sigma^2) (exp) or d^2 / (2 sigma^2)
// (gauss); what matters is x at the particle spacing d_hex. The kernels
// compute in float32 and the field backends count weights in units of 2^-40,
// so sigma far from the default either makes every weight 0 or every weight
// 1, and the run says nothing useful.
#include <optional>
#include <string>

#include "particles/particle_params.hpp"

namespace meshparticles {

// Throws UserError when 1 / (2 sigma^2) overflows float32: the kernels would
// compute 0 * inf = NaN for stacked particles.
void check_sigma_computable(const EnergyParams& energy);

// A one-line warning saying what the run will look like when sigma is so
// small that neighbouring particles no longer feel each other, or so large
// that every weight is 1 to within rounding; nothing otherwise.
std::optional<std::string> degenerate_sigma_warning(const EnergyParams& energy, double d_hex);

}  // namespace meshparticles
