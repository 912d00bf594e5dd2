// The holes particles leave in a surface: found between vertices as well as
// at them, and pulled shut by the particles whose cells reach into them,
// along the surface (not by a particle through the air).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "particles/hole_pull.hpp"
#include "folded_strip.hpp"

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

// The points of `mesh` nearest to `points`.
std::vector<SurfaceLocation> on(const SurfaceMesh& mesh, const std::vector<Vec3>& points) {
  const NearestSurfacePoint nearest(mesh);
  std::vector<SurfaceLocation> at;
  for (const Vec3& p : points) at.push_back(*nearest.find(p));
  return at;
}

std::unique_ptr<GeodesicSolver> solver_for(const SurfaceMesh& mesh) {
  return make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
}

// A hole between the vertices is found: particles on the corners leave the
// middle 0.707 away, where no vertex lies (the vertices alone say 0).
TEST(HolePull, FindsAHoleBetweenTheVertices) {
  const SurfaceMesh square = unit_square();
  const auto solver = solver_for(square);
  const HolePull holes(square, *solver, 0.05);
  EXPECT_GT(holes.size(), 200u);
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_NEAR(holes.cover(on(square, corners)), std::sqrt(0.5), 0.05);
  EXPECT_NEAR(holes.cover(on(square, grid())), std::sqrt(0.02), 0.02);
}

// A full grid has no point farther than its cells' half diagonal (0.141):
// no pull. A particle taken out of the middle leaves a hole its four
// neighbours are drawn into, each straight toward it; far particles stay.
TEST(HolePull, DrawsTheNeighboursOfAHoleIntoIt) {
  const SurfaceMesh square = unit_square();
  const auto solver = solver_for(square);
  SolverScratch scratch;
  HolePull holes(square, *solver, 0.02);
  for (const Vec3& pull : holes.pull(on(square, grid()), 0.15, 0.04, scratch)) EXPECT_EQ(norm(pull), 0.0);
  const std::vector<Vec3> at = grid({{0.5, 0.5, 0}});
  HolePull fresh(square, *solver, 0.02);
  const std::vector<Vec3> pulls = fresh.pull(on(square, at), 0.15, 0.04, scratch);
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
  const auto solver = solver_for(square);
  SolverScratch scratch;
  HolePull again(square, *solver, 0.02);
  std::vector<Vec3> at = grid({{0.5, 0.5, 0}, {0.1, 0.9, 0}});
  again.pull(on(square, at), 0.15, 0.04, scratch);
  for (Vec3& p : at) p = p + Vec3{0.004 * p.y, -0.003 * p.x, 0};
  HolePull fresh(square, *solver, 0.02);
  const std::vector<Vec3> expected = fresh.pull(on(square, at), 0.15, 0.04, scratch),
                          found = again.pull(on(square, at), 0.15, 0.04, scratch);
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_EQ(found[i].x, expected[i].x) << i;
    EXPECT_EQ(found[i].y, expected[i].y) << i;
  }
}

// More particles than two bytes can name, so that each point's particle is
// held in four: called again after small moves (each its own, so that a
// point given another particle's would be looked at or passed over amiss),
// still what a fresh look gives.
TEST(HolePull, AgainWithMoreParticlesThanTwoBytesNameGivesWhatAFreshLookGives) {
  // The unit square in 60 x 60 cells of two triangles each.
  constexpr int kCells = 60;
  std::vector<Vec3> corners;
  std::vector<Triangle> triangles;
  for (int i = 0; i <= kCells; ++i) {
    for (int j = 0; j <= kCells; ++j) corners.push_back({double(i) / kCells, double(j) / kCells, 0});
  }
  const auto corner = [](int i, int j) { return VertexId(i * (kCells + 1) + j); };
  for (int i = 0; i < kCells; ++i) {
    for (int j = 0; j < kCells; ++j) {
      triangles.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
      triangles.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
    }
  }
  const SurfaceMesh square(corners, triangles);
  const auto solver = solver_for(square);
  // A grid of 260 x 260 particles, less one in 50 (holes).
  constexpr int kSide = 260;
  constexpr double kSpacing = 1.0 / kSide;
  std::vector<Vec3> at;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      if ((7 * i + 3 * j) % 50 != 0) at.push_back({(i + 0.5) * kSpacing, (j + 0.5) * kSpacing, 0});
    }
  }
  ASSERT_GT(at.size(), 65536u);
  SolverScratch scratch;
  HolePull again(square, *solver, kSpacing);
  again.pull(on(square, at), 0.6 * kSpacing, kSpacing * kSpacing, scratch);
  for (Vec3& p : at) p = p + (0.02 * kSpacing) * Vec3{p.y, -p.x * p.x, 0};
  HolePull fresh(square, *solver, kSpacing);
  const std::vector<SurfaceLocation> moved = on(square, at);
  const std::vector<Vec3> expected = fresh.pull(moved, 0.6 * kSpacing, kSpacing * kSpacing, scratch),
                          found = again.pull(moved, 0.6 * kSpacing, kSpacing * kSpacing, scratch);
  std::size_t pulled = 0;
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_EQ(found[i].x, expected[i].x) << i;
    EXPECT_EQ(found[i].y, expected[i].y) << i;
    if (norm(expected[i]) > 0) ++pulled;
  }
  EXPECT_GT(pulled, 1000u);  // the holes draw their neighbours
}

// On a strip folded back on itself, particles cover one sheet and the
// other but for its end: that hole lies a twentieth of a spacing from the
// first sheet's particles through the air, and 1.5 along its own sheet from
// the nearest of its own. Its own sheet's particles are drawn toward it
// (along the sheet, to -x), the other sheet's not at all; and the cover is
// what the surface says, not the air.
TEST(HolePull, AHoleIsDrawnShutByParticlesOnItsOwnSheet) {
  const SurfaceMesh mesh = folded_strip();
  const auto solver = solver_for(mesh);
  std::vector<Vec3> points;
  std::vector<bool> on_the_hole_sheet;
  for (double x = 0.25; x < kLength; x += 0.5) {
    for (const double y : {0.5, 1.5}) {
      points.push_back({x, y, 2 * kBend});  // the sheet that covers
      on_the_hole_sheet.push_back(false);
      if (x < 1.5) continue;
      points.push_back({x, y, 0});
      on_the_hole_sheet.push_back(true);
    }
  }
  const std::vector<SurfaceLocation> at = on(mesh, points);
  HolePull holes(mesh, *solver, 0.1);
  SolverScratch scratch;
  const std::vector<Vec3> pulls = holes.pull(at, 0.6, 0.5, scratch);
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (!on_the_hole_sheet[i]) {
      EXPECT_EQ(norm(pulls[i]), 0.0) << i;
    } else if (points[i].x < 2) {
      EXPECT_LT(pulls[i].x, -0.1) << i;
    }
  }
  EXPECT_GT(holes.cover(at), 1.5);
}

}  // namespace
}  // namespace meshparticles::testing
