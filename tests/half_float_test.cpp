#include "common/half_float.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace meshparticles {
namespace {

bool is_nan_half(std::uint16_t bits) { return (bits & 0x7c00u) == 0x7c00u && (bits & 0x3ffu) != 0; }

// Every half that is not a NaN, from -infinity up to +infinity, in order of value.
std::vector<std::uint16_t> halves_in_order() {
  std::vector<std::uint16_t> ordered;
  for (std::uint32_t bits = 0xfc00u; bits > 0x8000u; --bits) ordered.push_back(std::uint16_t(bits));
  for (std::uint32_t bits = 0; bits <= 0x7c00u; ++bits) ordered.push_back(std::uint16_t(bits));
  return ordered;  // -0 left out: it equals +0
}

TEST(HalfFloat, EveryHalfComesBackFromItsFloat) {
  for (std::uint32_t bits = 0; bits <= 0xffffu; ++bits) {
    const auto half = std::uint16_t(bits);
    const float wide = float_from_half_bits(half);
    if (is_nan_half(half)) {
      EXPECT_TRUE(std::isnan(wide)) << bits;
      EXPECT_TRUE(is_nan_half(half_bits_nearest(wide))) << bits;
    } else {
      EXPECT_EQ(half_bits_nearest(wide), half) << bits;
    }
  }
  EXPECT_EQ(float_from_half_bits(0x3c00u), 1.0f);
  EXPECT_EQ(float_from_half_bits(0x7bffu), 65504.0f);
  EXPECT_EQ(float_from_half_bits(0x0001u), 0x1p-24f);
  EXPECT_EQ(float_from_half_bits(0x7c00u), std::numeric_limits<float>::infinity());
}

// Between two neighbouring halves, below the midpoint rounds down, above it
// up, and the midpoint itself to the one with an even last bit.
TEST(HalfFloat, RoundsToTheNearestAndTiesToEven) {
  const std::vector<std::uint16_t> ordered = halves_in_order();
  for (std::size_t k = 0; k + 1 < ordered.size(); ++k) {
    const std::uint16_t low = ordered[k], high = ordered[k + 1];
    const float a = float_from_half_bits(low), b = float_from_half_bits(high);
    if (std::isinf(a) || std::isinf(b)) continue;  // beyond the largest half: below
    const float middle = a + (b - a) / 2;  // exact: halves have 11 significant bits
    const std::uint16_t even = (low & 1u) == 0 ? low : high;
    const float infinity = std::numeric_limits<float>::infinity();
    // By value, so that -0 (what a tiny negative float rounds to) equals +0.
    const auto rounded = [](float value) { return float_from_half_bits(half_bits_nearest(value)); };
    EXPECT_EQ(rounded(middle), float_from_half_bits(even)) << low;
    EXPECT_EQ(rounded(std::nextafter(middle, -infinity)), a) << low;
    EXPECT_EQ(rounded(std::nextafter(middle, infinity)), b) << low;
    EXPECT_EQ(rounded(std::nextafter(a, infinity)), a) << low;
    EXPECT_EQ(rounded(std::nextafter(b, -infinity)), b) << low;
  }
  // Past the largest half: 65520 is halfway to 65536 and rounds up to infinity.
  EXPECT_EQ(half_bits_nearest(65519.99f), 0x7bffu);
  EXPECT_EQ(half_bits_nearest(65520.0f), 0x7c00u);
  EXPECT_EQ(half_bits_nearest(-1e30f), 0xfc00u);
  EXPECT_EQ(half_bits_nearest(0x1p-25f), 0x0000u);  // the tie below the smallest subnormal: to 0
  EXPECT_EQ(half_bits_nearest(std::nextafter(0x1p-25f, 1.0f)), 0x0001u);
  EXPECT_EQ(half_bits_nearest(std::numeric_limits<float>::denorm_min()), 0x0000u);
  EXPECT_EQ(half_bits_nearest(-0.0f), 0x8000u);
}

#if defined(__FLT16_MAX__)
// Where the compiler has _Float16, its conversion agrees on floats spread
// over every exponent (every 1021st bit pattern, 4.2 million of them).
TEST(HalfFloat, AgreesWithTheCompilersFloat16) {
  std::size_t differing = 0;
  for (std::uint64_t bits = 0; bits <= 0xffffffffu; bits += 1021) {
    const float value = std::bit_cast<float>(std::uint32_t(bits));
    if (std::isnan(value)) continue;
    const auto expected = std::bit_cast<std::uint16_t>(static_cast<_Float16>(value));
    if (half_bits_nearest(value) != expected && ++differing <= 5) {
      ADD_FAILURE() << "float bits " << std::hex << bits << ": " << half_bits_nearest(value) << " against "
                    << expected;
    }
  }
  EXPECT_EQ(differing, 0u);
}
#endif

}  // namespace
}  // namespace meshparticles
