// Which particles are neighbours along the surface: on a strip folded back
// on itself, a particle on the other sheet, a twentieth of a spacing away
// through the air, is surely not; one beside it on its own sheet is, at no
// more than its distance.
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

}  // namespace
}  // namespace meshparticles::testing
