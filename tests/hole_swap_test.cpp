// A particle carried from a crowd into the widest hole near it: one swap
// ends a close pair and a hole that pushes and pulls hold in balance.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "particles/hole_swap.hpp"

namespace meshparticles::testing {
namespace {

// The unit square in z = 0, a grid of `cells` x `cells` squares, each cut in two.
SurfaceMesh square_grid(int cells) {
  std::vector<Vec3> positions;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) positions.push_back({double(i) / cells, double(j) / cells, 0});
  }
  std::vector<Triangle> triangles;
  const auto at = [&](int i, int j) { return VertexId(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

// Particles at the centres of a 5 x 5 grid of cells 0.2 wide (0.2 apart,
// no point of the square farther than 0.141 from one), less the middle
// one where `hole`, and with `extra` added last.
std::vector<SurfaceLocation> grid_particles(const SurfaceMesh& mesh, bool hole, const std::vector<Vec3>& extra) {
  const NearestSurfacePoint nearest(mesh);
  std::vector<SurfaceLocation> at;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      if (hole && i == 2 && j == 2) continue;
      at.push_back(*nearest.find({0.1 + 0.2 * i, 0.1 + 0.2 * j, 0}));
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
