#pragma once
// IEEE 754 binary16 ("half") in plain C++: a float rounded to the nearest
// half (ties to even, as the device's vstore_half_rte), and a half widened
// back. Written out rather than through _Float16, which not every compiler
// has on x86-64 (clang before 15), so that any C++20 compiler builds the
// field backends' serial twins bit for bit.
#include <bit>
#include <cstdint>

namespace meshparticles {

// The half nearest to `value` (ties to even); beyond the largest half,
// infinity; a NaN stays a NaN (quiet, its payload's top bits kept).
inline std::uint16_t half_bits_nearest(float value) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const auto sign = static_cast<std::uint16_t>((bits >> 16) & 0x8000u);
  const std::uint32_t magnitude = bits & 0x7fffffffu;
  constexpr std::uint32_t kInfinityBits = 0x7f800000u;
  constexpr std::uint32_t kSmallestNormalHalf = 0x38800000u;  // 2^-14 as a float
  constexpr std::uint32_t kHalfOfSmallestSubnormal = 0x33000000u;  // 2^-25: a tie that rounds to 0
  constexpr std::uint32_t kFirstToInfinity = 0x477ff000u;  // 65520: halfway past the largest half
  if (magnitude > kInfinityBits) return sign | 0x7e00u | static_cast<std::uint16_t>((magnitude >> 13) & 0x3ffu);
  if (magnitude >= kFirstToInfinity) return sign | 0x7c00u;
  if (magnitude <= kHalfOfSmallestSubnormal) return sign;
  std::uint32_t kept;  // the half's bits before rounding
  std::uint32_t dropped;  // the bits shifted out, and the tie's pattern
  std::uint32_t tie;
  if (magnitude < kSmallestNormalHalf) {
    // A subnormal half counts units of 2^-24: the float's 24-bit significand shifted right.
    const std::uint32_t significand = (magnitude & 0x7fffffu) | 0x800000u;
    const std::uint32_t shift = 126u - (magnitude >> 23);  // 14 to 24
    kept = significand >> shift;
    dropped = significand & ((1u << shift) - 1u);
    tie = 1u << (shift - 1u);
  } else {
    // Rebias the exponent (127 to 15) and keep the top 10 of 23 mantissa bits.
    const std::uint32_t rebased = magnitude - (112u << 23);
    kept = rebased >> 13;
    dropped = rebased & 0x1fffu;
    tie = 0x1000u;
  }
  // A carry out of the mantissa steps the exponent up, as it should.
  if (dropped > tie || (dropped == tie && (kept & 1u) != 0)) ++kept;
  return sign | static_cast<std::uint16_t>(kept);
}

// The half `bits` as a float (exact: every half is a float).
inline float float_from_half_bits(std::uint16_t bits) {
  const std::uint32_t sign = std::uint32_t(bits & 0x8000u) << 16;
  const std::uint32_t exponent = (bits >> 10) & 0x1fu;
  const std::uint32_t mantissa = bits & 0x3ffu;
  if (exponent == 0) {
    const float magnitude = float(mantissa) * 0x1p-24f;  // subnormal or zero: exact
    return sign != 0 ? -magnitude : magnitude;
  }
  if (exponent == 0x1fu) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
  return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

// `value` rounded to the nearest half, as a float.
inline float rounded_to_half(float value) { return float_from_half_bits(half_bits_nearest(value)); }

}  // namespace meshparticles
