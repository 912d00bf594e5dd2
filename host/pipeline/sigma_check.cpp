#include "pipeline/sigma_check.hpp"

#include <cmath>

#include "common/text_format.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// exp(-x) below 2^-40 (x > 27.7) is 0 in the field backends' units and
// beyond 1e-12 of anything the direct sums can tell apart.
constexpr double kVanishingExponent = 27.7;
// exp(-x) within 1e-6 of 1: a few float32 steps from 1, so the candidates'
// energies differ by rounding, not by distance.
constexpr double kFlatExponent = 1e-6;

}  // namespace

void check_sigma_computable(const EnergyParams& energy) {
  const float factor = float(energy.inv_two_sigma_sq());
  if (!std::isfinite(factor)) {
    throw UserError("--sigma " + format_number("%g", energy.sigma) +
                    " is too small to compute with: 1/(2 sigma^2) overflows float32 (sigma must be above about 4e-20)");
  }
}

std::optional<std::string> degenerate_sigma_warning(const EnergyParams& energy, double d_hex) {
  const double spacing = distance_term(energy.potential, d_hex);
  const double exponent = spacing * energy.inv_two_sigma_sq();
  const std::string given = "--sigma " + format_number("%g", energy.sigma) + " with d_hex " +
                            format_number("%.4g", d_hex) + ": two particles at that spacing weigh exp(-" +
                            format_number("%.3g", exponent) + ")";
  if (exponent > kVanishingExponent) {
    return given + ", 0 to the kernels: particles will not feel each other and will hardly move";
  }
  if (exponent < kFlatExponent) {
    return given + ", 1 to within rounding: the energy is flat and moves follow rounding, not distance";
  }
  return std::nullopt;
}

}  // namespace meshparticles
