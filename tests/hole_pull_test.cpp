// The holes particles leave in a surface: found between vertices as well as
// at them, and pulled shut by the particles whose cells reach into them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "particles/hole_pull.hpp"

namespace meshparticles::testing {
namespace {

// The unit square in z = 0, two triangles: no vertex inside it.
SurfaceMesh unit_square() {
  return SurfaceMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {Triangle{0, 1, 2}, Triangle{0, 2, 3}});
}

// Particles at the centres of a 5 x 5 grid of cells 0.2 wide, less those at `missing`.
std::vector<Vec3> grid(const std::vector<Vec3>& missing = {}) {
  std::vector<Vec3> at;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const Vec3 p{0.1 + 0.2 * i, 0.1 + 0.2 * j, 0};
      bool gone = false;
      for (const Vec3& m : missing) gone = gone || distance(p, m) < 1e-9;
      if (!gone) at.push_back(p);
    }
  }
  return at;
}

// A hole between the vertices is found: particles on the corners leave the
// middle 0.707 away, where no vertex lies (the vertices alone say 0).
TEST(HolePull, FindsAHoleBetweenTheVertices) {
  const SurfaceMesh square = unit_square();
  const HolePull holes(square, 0.05);
  EXPECT_GT(holes.size(), 200u);
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_NEAR(holes.cover(corners), std::sqrt(0.5), 0.05);
  EXPECT_NEAR(holes.cover(grid()), std::sqrt(0.02), 0.02);
}

// A full grid has no point farther than its cells' half diagonal (0.141):
// no pull. A particle taken out of the middle leaves a hole its four
// neighbours are drawn into, each straight toward it; far particles stay.
TEST(HolePull, DrawsTheNeighboursOfAHoleIntoIt) {
  const SurfaceMesh square = unit_square();
  HolePull holes(square, 0.02);
  for (const Vec3& pull : holes.pull(grid(), 0.15, 0.04)) EXPECT_EQ(norm(pull), 0.0);
  const std::vector<Vec3> at = grid({{0.5, 0.5, 0}});
  const std::vector<Vec3> pulls = holes.pull(at, 0.15, 0.04);
  for (std::size_t i = 0; i < at.size(); ++i) {
    const Vec3 toward = Vec3{0.5, 0.5, 0} - at[i];
    if (std::abs(norm(toward) - 0.2) < 1e-9) {
      EXPECT_GT(dot(pulls[i], toward), 0.9 * norm(pulls[i]) * norm(toward)) << i;
      EXPECT_GT(norm(pulls[i]), 0.0) << i;
    } else if (norm(toward) > 0.35) {
      EXPECT_EQ(norm(pulls[i]), 0.0) << i;
    }
  }
}

// Called again with the particles moved, it looks only at the points their
// moves may have taken beyond the reach, and gives what a fresh look gives.
TEST(HolePull, AgainAfterSmallMovesGivesWhatAFreshLookGives) {
  const SurfaceMesh square = unit_square();
  HolePull again(square, 0.02);
  std::vector<Vec3> at = grid({{0.5, 0.5, 0}, {0.1, 0.9, 0}});
  again.pull(at, 0.15, 0.04);
  for (Vec3& p : at) p = p + Vec3{0.004 * p.y, -0.003 * p.x, 0};
  HolePull fresh(square, 0.02);
  const std::vector<Vec3> expected = fresh.pull(at, 0.15, 0.04), found = again.pull(at, 0.15, 0.04);
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_EQ(found[i].x, expected[i].x) << i;
    EXPECT_EQ(found[i].y, expected[i].y) << i;
  }
}

}  // namespace
}  // namespace meshparticles::testing
