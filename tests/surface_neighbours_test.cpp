// Which particles are neighbours along the surface: on a strip folded back
// on itself, a particle on the other sheet, a twentieth of a spacing away
// through the air, is surely not; one beside it on its own sheet is, at no
// more than its distance. Asked step after step, the answers kept from one
// step hold only while the particles have not moved enough to change them.
#include <gtest/gtest.h>

#include <memory>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "particles/surface_neighbours.hpp"
#include "folded_strip.hpp"

namespace meshparticles::testing {
namespace {

TEST(SurfaceNeighbours, APairFacingAcrossAFoldIsNotOneBesideIs) {
  const SurfaceMesh mesh = folded_strip();
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(mesh);
  const SurfaceLocation from = *nearest.find({1, 1, 0});
  const SurfaceLocation across = *nearest.find({1, 1, 2 * kBend});
  const SurfaceLocation beside = *nearest.find({1.5, 1.2, 0});
  const SurfaceNeighbours surface(mesh, *solver);
  LookScratch scratch;
  surface.look_from(from, 1.0, scratch);
  EXPECT_GE(surface.at_least(across, scratch), 1.0);  // about 6 along the surface
  const double apart = distance(from.at, beside.at);
  EXPECT_LE(surface.at_least(beside, scratch), apart * 1.01);
  EXPECT_GT(surface.at_least(beside, scratch), apart * 0.8);
  // Looked at from the other sheet, the same.
  surface.look_from(across, 1.0, scratch);
  EXPECT_GE(surface.at_least(from, scratch), 1.0);
}

// One scratch lent to looks along two surfaces in turn, the smaller first
// (a thread's, shape after shape): every answer is what a look with a
// scratch of its own gives, to the bit.
TEST(SurfaceNeighbours, AScratchLentToTwoSurfacesInTurnAnswersAsItsOwn) {
  const SurfaceMesh once = folded_strip(), twice = folded_strip(2);
  ASSERT_LT(once.vertex_count(), twice.vertex_count());
  const std::unique_ptr<GeodesicSolver> once_solver = make_geodesic_solver(once, GeodesicMethod::fast_marching),
                                        twice_solver = make_geodesic_solver(twice, GeodesicMethod::fast_marching);
  const SurfaceNeighbours along_once(once, *once_solver), along_twice(twice, *twice_solver);
  const NearestSurfacePoint near_once(once), near_twice(twice);
  std::vector<SurfaceLocation> on_once, on_twice;
  for (double x = 0.5; x < kLength; x += 0.5) {
    for (const double z : {0.0, 2 * kBend, 4 * kBend}) {
      on_once.push_back(*near_once.find({x, 1, z}));
      on_twice.push_back(*near_twice.find({x, 1, z}));
    }
  }
  LookScratch lent;
  for (int turn = 0; turn < 2; ++turn) {
    for (std::size_t from = 0; from < on_once.size(); from += 5) {
      for (const auto& [surface, at] : {std::pair(&along_once, &on_once), std::pair(&along_twice, &on_twice)}) {
        LookScratch own;
        surface->look_from((*at)[from], 1.0, own);
        surface->look_from((*at)[from], 1.0, lent);
        for (const SurfaceLocation& to : *at) EXPECT_EQ(surface->at_least(to, lent), surface->at_least(to, own));
      }
    }
  }
}

TEST(SurfacePairs, KeepAnAnswerOnlyWhileTheMovesCannotChangeIt) {
  const SurfaceMesh mesh = folded_strip();
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(mesh);
  SurfacePairs pairs(mesh, *solver);
  LookScratch scratch;
  std::vector<SurfaceLocation> at{*nearest.find({1, 1, 0}), *nearest.find({1, 1, 2 * kBend}),
                                  *nearest.find({1.5, 1.2, 0})};
  pairs.begin_step(at, scratch);
  EXPECT_FALSE(pairs.may_be_within(0, 1, 1.0));
  EXPECT_TRUE(pairs.may_be_within(0, 2, 1.0));
  // A little moved: the same answers.
  at = {*nearest.find({1.02, 1, 0}), *nearest.find({1.01, 1.01, 2 * kBend}), *nearest.find({1.52, 1.2, 0})};
  pairs.begin_step(at, scratch);
  EXPECT_FALSE(pairs.may_be_within(0, 1, 1.0));
  EXPECT_TRUE(pairs.may_be_within(0, 2, 1.0));
  // The particle across the fold comes round to this sheet, beside the first.
  at[1] = *nearest.find({1.3, 0.8, 0});
  pairs.begin_step(at, scratch);
  EXPECT_TRUE(pairs.may_be_within(0, 1, 1.0));
}

}  // namespace
}  // namespace meshparticles::testing
