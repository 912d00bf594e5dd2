#pragma once
// The serial twin's copy of kernels/field.h: how a weight is stored and how
// the field F(v) = sum_i W[p_i][v] counts it, bit for bit. Keep the two in
// step; docs/ALGORITHM.md ("The field backend") says why fixed point.
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "common/half_float.hpp"
#include "common/user_error.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

// F is kept in 64-bit integers counting units of 2^-40: exact sums.
inline constexpr float kFieldUnitsPerWeight = 0x1p40f;

// F <= n * 2^40 must stay below 2^63.
inline constexpr std::size_t kMaxFieldParticles = std::size_t{1} << 22;

// Refuses more particles than that (UserError), for every field backend.
inline void check_field_particle_count(std::size_t particles) {
  if (particles > kMaxFieldParticles) {
    throw UserError("the field backend takes at most " + std::to_string(kMaxFieldParticles) + " particles (" +
                    std::to_string(particles) + " asked): its 64-bit field would overflow");
  }
}

// w(d) as the kernels compute it (particle_energy.h): in float.
inline float pair_weight_float(Potential potential, float d, float inv_two_sigma_sq) {
  return std::exp(-distance_term(potential, d) * inv_two_sigma_sq);
}

// The weight as the table stores it: float32, or rounded to the nearest half
// (as vstore_half_rte does on the device).
inline float stored_weight(WeightFormat format, float weight) {
  return format == WeightFormat::half ? rounded_to_half(weight) : weight;
}

// Truncated to whole units, as convert_long does.
inline std::int64_t field_units(float weight) { return static_cast<std::int64_t>(weight * kFieldUnitsPerWeight); }

// One rounding to the float the candidate rule compares.
inline float field_energy(std::int64_t units) { return float(units) * (1.0f / kFieldUnitsPerWeight); }

// The total pair energy from each particle's energy where it is, in field
// units: summed exactly (n * 2^63 fits 128 bits) and rounded to a double
// once, so every field backend, and the device's one-launch iterations that
// compare energies as these doubles compare (field_iterations.cl), agree
// whatever the order of the sum. Every pair is counted from both ends.
inline double pair_energy_of_total(std::uint64_t total_units) {
  return double(total_units) / (2.0 * double(kFieldUnitsPerWeight));
}

class FieldEnergySum {
 public:
  void add(std::int64_t particle_units) { units_ += static_cast<Units>(particle_units); }
  // The same rounding as pair_energy_of_total where the sum fits 64 bits.
  double pair_energy() const { return double(units_) / (2.0 * double(kFieldUnitsPerWeight)); }

 private:
  __extension__ typedef unsigned __int128 Units;
  Units units_ = 0;
};

inline double pair_energy(std::span<const std::int64_t> particle_units) {
  FieldEnergySum sum;
  for (const std::int64_t units : particle_units) sum.add(units);
  return sum.pair_energy();
}

}  // namespace meshparticles
