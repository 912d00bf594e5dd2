#pragma once
// The serial twin's copy of kernels/field.h: how a weight is stored and how
// the field F(v) = sum_i W[p_i][v] counts it, bit for bit. Keep the two in
// step; docs/ALGORITHM.md ("The field backend") says why fixed point.
#include <cmath>
#include <cstdint>

#include "particles/particle_params.hpp"

namespace meshparticles {

// F is kept in 64-bit integers counting units of 2^-40: exact sums.
inline constexpr float kFieldUnitsPerWeight = 0x1p40f;

// F <= n * 2^40 must stay below 2^63.
inline constexpr std::size_t kMaxFieldParticles = std::size_t{1} << 22;

// w(d) as the kernels compute it (particle_energy.h): in float.
inline float pair_weight_float(Potential potential, float d, float inv_two_sigma_sq) {
  return std::exp(-(potential == Potential::exp ? d : d * d) * inv_two_sigma_sq);
}

// The weight as the table stores it: float32, or rounded to the nearest half
// (as vstore_half_rte does on the device).
inline float stored_weight(WeightFormat format, float weight) {
  return format == WeightFormat::half ? float(_Float16(weight)) : weight;
}

// Truncated to whole units, as convert_long does.
inline std::int64_t field_units(float weight) { return static_cast<std::int64_t>(weight * kFieldUnitsPerWeight); }

// One rounding to the float the candidate rule compares.
inline float field_energy(std::int64_t units) { return float(units) * (1.0f / kFieldUnitsPerWeight); }

}  // namespace meshparticles
