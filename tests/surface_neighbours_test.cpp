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
  SurfaceNeighbours surface(mesh, *solver);
  surface.look_from(from, 1.0);
  EXPECT_GE(surface.at_least(across), 1.0);  // about 6 along the surface
  const double apart = distance(from.at, beside.at);
  EXPECT_LE(surface.at_least(beside), apart * 1.01);
  EXPECT_GT(surface.at_least(beside), apart * 0.8);
  // Looked at from the other sheet, the same.
  surface.look_from(across, 1.0);
  EXPECT_GE(surface.at_least(from), 1.0);
}

TEST(SurfacePairs, KeepAnAnswerOnlyWhileTheMovesCannotChangeIt) {
  const SurfaceMesh mesh = folded_strip();
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(mesh);
  SurfacePairs pairs(mesh, *solver);
  std::vector<SurfaceLocation> at{*nearest.find({1, 1, 0}), *nearest.find({1, 1, 2 * kBend}),
                                  *nearest.find({1.5, 1.2, 0})};
  pairs.begin_step(at);
  EXPECT_FALSE(pairs.may_be_within(0, 1, 1.0));
  EXPECT_TRUE(pairs.may_be_within(0, 2, 1.0));
  // A little moved: the same answers.
  at = {*nearest.find({1.02, 1, 0}), *nearest.find({1.01, 1.01, 2 * kBend}), *nearest.find({1.52, 1.2, 0})};
  pairs.begin_step(at);
  EXPECT_FALSE(pairs.may_be_within(0, 1, 1.0));
  EXPECT_TRUE(pairs.may_be_within(0, 2, 1.0));
  // The particle across the fold comes round to this sheet, beside the first.
  at[1] = *nearest.find({1.3, 0.8, 0});
  pairs.begin_step(at);
  EXPECT_TRUE(pairs.may_be_within(0, 1, 1.0));
}

}  // namespace
}  // namespace meshparticles::testing
