// The host's share of the kernels' arithmetic (kernels/cavity_centre.h,
// kernels/surface_voronoi_round.h) gives the device's bits, and a run the
// same particles on every CPU, only where no multiply and add is fused into
// one rounding: CMakeLists.txt builds everything with -ffp-contract=off.
// Here a sum compiled for a CPU with FMA must still round twice.
#include <gtest/gtest.h>

#include "fused_multiply_add_probe.hpp"

namespace {

TEST(FusedMultiplyAdd, NoProductAndSumIsFusedIntoOneRounding) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (!__builtin_cpu_supports("fma")) GTEST_SKIP() << "this CPU has no fused multiply-add: the probe cannot run";
#endif
  // (1 + 2^-30)(1 - 2^-30) = 1 - 2^-60 rounds to 1, and + (-1) gives 0;
  // fused, the product keeps its 2^-60 and the sum is -2^-60.
  volatile double a = 1 + 0x1p-30, b = 1 - 0x1p-30, c = -1;
  EXPECT_EQ(product_plus_sum(a, b, c), 0.0);
}

}  // namespace
