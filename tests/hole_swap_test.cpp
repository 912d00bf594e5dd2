// A particle carried from a crowd into the widest hole near it: one swap
// ends a close pair and a hole that pushes and pulls hold in balance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "particles/hole_swap.hpp"
#include "square_grid.hpp"

namespace meshparticles::testing {
namespace {

// Particles at the centres of a `cells` x `cells` grid (5 x 5: 0.2 apart,
// no point of the square farther than 0.141 from one), less the middle
// one where `hole`, and with `extra` added last.
std::vector<SurfaceLocation> grid_particles(const SurfaceMesh& mesh, bool hole, const std::vector<Vec3>& extra,
                                            int cells = 5) {
  const NearestSurfacePoint nearest(mesh);
  std::vector<SurfaceLocation> at;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      if (hole && 2 * i + 1 == cells && 2 * j + 1 == cells) continue;
      at.push_back(*nearest.find({(i + 0.5) / cells, (j + 0.5) / cells, 0}));
    }
  }
  for (const Vec3& p : extra) at.push_back(*nearest.find(p));
  return at;
}

HoleSwapLimits limits(std::size_t swaps) {
  HoleSwapLimits wanted;
  wanted.max_swaps = swaps;
  wanted.spacing = 0.15;
  wanted.cover = 0.16;
  wanted.hole_step = 0.01;
  return wanted;
}

// A particle 0.06 from another and a hole 0.2 wide two neighbours away:
// one particle goes to the hole's middle, the rest stay where they were,
// and both figures end within their limits.
TEST(HoleSwap, ACrowdedParticleGoesIntoTheHoleBesideIt) {
  const SurfaceMesh square = square_grid(40);
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const SurfaceNeighbours surface(square, *solver);
  LookScratch look;
  const std::vector<SurfaceLocation> before = grid_particles(square, true, {{0.36, 0.3, 0}});
  std::vector<SurfaceLocation> after = before;
  const HoleSwapOutcome outcome = swap_into_holes(square, *solver, surface, look, after, limits(8));
  EXPECT_EQ(outcome.swaps, 1u);
  EXPECT_GE(outcome.smallest, 0.15);
  EXPECT_LE(outcome.cover, 0.16);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (distance(before[i].at, after[i].at) == 0) continue;
    ++moved;
    EXPECT_LT(distance(after[i].at, {0.5, 0.5, 0}), 1e-12) << i;
  }
  EXPECT_EQ(moved, 1u);
}

// A crowd at a corner (a pair 0.45 spacings apart) and a hole in the
// middle (a spacing wide), no local swap allowed (no steps): where the
// pair is under `carry_below` (a spacing) or the hole wider than
// `carry_above` (0.9 of one; FAUST's tr_reg_007 at n = 256 kept a hole
// 1.28x its template's with no pair under carry_below), a particle of the
// crowd is carried into the hole, each on the way taking the next one's
// place, so that none moves farther than a neighbour's place (a grid
// spacing and a half); otherwise (carry_below 0.3, no carry_above) nothing
// moves.
TEST(HoleSwap, ACrowdFarFromTheHoleIsCarriedIntoItStepByStep) {
  const SurfaceMesh square = square_grid(36);
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const SurfaceNeighbours surface(square, *solver);
  LookScratch look;
  const double spacing = 1.0 / 9;
  const std::vector<SurfaceLocation> before = grid_particles(square, true, {{0.02, 0.02, 0}}, 9);
  HoleSwapLimits wanted;
  wanted.max_swaps = 8;
  wanted.spacing = 0.95 * spacing;
  wanted.cover = 2 * spacing;  // only the crowd falls short
  wanted.hole_step = 0.005;
  wanted.steps = 0;
  enum class Carry { never, for_the_pair, for_the_hole };
  for (const Carry carry : {Carry::never, Carry::for_the_pair, Carry::for_the_hole}) {
    SCOPED_TRACE(int(carry));
    wanted.carry_below = carry == Carry::for_the_pair ? wanted.spacing : 0.3 * spacing;
    wanted.carry_above = carry == Carry::for_the_hole ? 0.9 * spacing : std::numeric_limits<double>::infinity();
    std::vector<SurfaceLocation> after = before;
    const HoleSwapOutcome outcome = swap_into_holes(square, *solver, surface, look, after, wanted);
    if (carry == Carry::never) {
      EXPECT_EQ(outcome.swaps, 0u);
      continue;
    }
    EXPECT_EQ(outcome.swaps, 1u);
    EXPECT_GE(outcome.smallest, wanted.spacing);
    EXPECT_LT(outcome.cover, 0.85 * spacing);  // the middle, a spacing from the nearest, is filled
    std::size_t moved = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
      const double move = distance(before[i].at, after[i].at);
      if (move == 0) continue;
      ++moved;
      EXPECT_LT(move, 1.5 * spacing) << i;
    }
    EXPECT_GE(moved, 4u);  // the corner is four steps or more from the middle
  }
}

// A set within both limits is left as it is, and so is any set when no
// swap is allowed.
TEST(HoleSwap, NothingMovesWithinTheLimitsOrWithNoSwapAllowed) {
  const SurfaceMesh square = square_grid(40);
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const SurfaceNeighbours surface(square, *solver);
  LookScratch look;
  for (const bool crowded : {false, true}) {
    const std::vector<SurfaceLocation> before =
        crowded ? grid_particles(square, true, {{0.36, 0.3, 0}}) : grid_particles(square, false, {});
    std::vector<SurfaceLocation> after = before;
    const HoleSwapOutcome outcome = swap_into_holes(square, *solver, surface, look, after, limits(crowded ? 0 : 8));
    EXPECT_EQ(outcome.swaps, 0u) << crowded;
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(distance(before[i].at, after[i].at), 0.0) << i;
  }
}

}  // namespace
}  // namespace meshparticles::testing
