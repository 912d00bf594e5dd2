// The centre of a particle's cavity (particles/cavity_centre): on the flat
// patch, where the answer is plane geometry, the point of a particle's
// region farthest from three neighbours is the centre of the circle
// through them, off the vertices; a particle further out counts where it
// comes near the cavity and changes nothing where it does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <numbers>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "mesh/surface_walk.hpp"
#include "particles/cavity_centre.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {

struct Scene {
  SurfaceMesh patch = committed("patch.off");
  SurfaceWalk walk{patch};
  CavitySurface surface{patch, walk.triangles_around()};
  std::vector<SurfaceLocation> points;
  std::vector<vec3d> positions;
  ParticleBalls balls{0};

  // Particle 0 at `at`, then the others; each one's ball marched.
  explicit Scene(const std::vector<Vec3>& at) {
    const NearestSurfacePoint nearest(patch);
    const auto solver = make_geodesic_solver(patch, GeodesicMethod::fast_marching);
    SolverScratch scratch;
    balls = ParticleBalls(at.size());
    ParticleBall ball;
    for (const Vec3& p : at) {
      points.push_back(*nearest.find(p));
      const Triangle& t = patch.triangles()[points.back().triangle];
      const auto& x = patch.positions();
      const double starts[3] = {distance(p, x[t[0]]), distance(p, x[t[1]]), distance(p, x[t[2]])};
      solver->solve_ball_from(t, starts, INFINITY, scratch, ball);
      std::sort(ball.begin(), ball.end());
      balls.set(std::uint32_t(positions.size()), ball);
      positions.push_back(to_vec3d(points.back().at));
    }
  }

  // Particle 0's region: the vertices nearer it than any other (a plane).
  std::vector<VertexId> region() const {
    std::vector<VertexId> mine;
    for (VertexId v = 0; v < patch.vertex_count(); ++v) {
      bool nearest = true;
      for (std::size_t k = 1; k < points.size(); ++k) {
        nearest = nearest && distance(patch.positions()[v], points[0].at) < distance(patch.positions()[v], points[k].at);
      }
      if (nearest) mine.push_back(v);
    }
    return mine;
  }

  CavityCentre centre(const std::vector<std::uint32_t>& near, const std::vector<std::uint32_t>& further) const {
    const std::vector<VertexId> mine = region();
    CavityScratch scratch;
    return cavity_centre(surface, {points[0], mine, near, further}, positions, balls, scratch);
  }
};

// Three neighbours on a circle of radius 0.25 about the patch's middle,
// and three more at 0.4 between them, which close the particle's region
// off from the patch's border (the widest circle in it is then the inner
// three's: checked on a grid of 300 x 300 points).
std::vector<Vec3> three_around(Vec3 particle) {
  std::vector<Vec3> at{particle};
  for (const auto& [degrees, radius] : {std::pair{90.0, 0.25}, {210.0, 0.25}, {330.0, 0.25}, {30.0, 0.4}, {150.0, 0.4}, {270.0, 0.4}}) {
    const double a = degrees * std::numbers::pi / 180;
    at.push_back({0.5 + radius * std::cos(a), 0.5 + radius * std::sin(a), 0});
  }
  return at;
}

TEST(CavityCentre, OnAPlaneItIsTheCentreOfTheCircleThroughThreeNeighbours) {
  const Vec3 particle{0.56, 0.47, 0};
  const Scene scene(three_around(particle));
  const double edge = scene.patch.mean_edge_length();
  const CavityCentre centre = scene.centre({1, 2, 3, 4, 5, 6}, {});
  const Vec3 middle{0.5, 0.5, 0};
  std::printf("centre %.5f %.5f (off by %.4f edges), away %.5f, here %.5f\n", centre.at.at.x, centre.at.at.y,
              distance(centre.at.at, middle) / edge, centre.away, centre.here);
  // Off the vertices: the patch's nearest vertex is a third of an edge from the middle.
  EXPECT_LT(distance(centre.at.at, middle), 0.05 * edge);
  EXPECT_NEAR(centre.away, 0.25, 0.02 * edge);
  double nearest = INFINITY;
  for (std::size_t k = 1; k < scene.points.size(); ++k) nearest = std::min(nearest, distance(particle, scene.points[k].at));
  EXPECT_NEAR(centre.here, nearest, 0.02 * edge);
  // The point found is where the weights say, in the triangle named.
  const Triangle& t = scene.patch.triangles()[centre.at.triangle];
  const auto& x = scene.patch.positions();
  const Vec3 weighed = centre.at.weights[0] * x[t[0]] + centre.at.weights[1] * x[t[1]] + centre.at.weights[2] * x[t[2]];
  EXPECT_LT(distance(weighed, centre.at.at), 1e-9);
}

// A particle further out: far from the cavity it changes nothing; at its
// centre it counts as a neighbour would (its straight line bounds its way
// along the surface from below, so leaving it out where that line is long
// is safe).
TEST(CavityCentre, AParticleFurtherOutCountsOnlyWhereItComesNear) {
  const Vec3 particle{0.56, 0.47, 0};
  std::vector<Vec3> far = three_around(particle), close = three_around(particle);
  far.push_back({0.05, 0.95, 0});
  close.push_back({0.5, 0.5, 0});
  const CavityCentre alone = Scene(far).centre({1, 2, 3, 4, 5, 6}, {});
  const CavityCentre with_far = Scene(far).centre({1, 2, 3, 4, 5, 6}, {7});
  EXPECT_EQ(alone.at.triangle, with_far.at.triangle);
  EXPECT_EQ(alone.at.at.x, with_far.at.at.x);
  EXPECT_EQ(alone.away, with_far.away);
  const CavityCentre with_close = Scene(close).centre({1, 2, 3, 4, 5, 6}, {7});
  const CavityCentre close_as_near = Scene(close).centre({1, 2, 3, 4, 5, 6, 7}, {});
  EXPECT_EQ(with_close.at.triangle, close_as_near.at.triangle);
  EXPECT_EQ(with_close.at.at.x, close_as_near.at.at.x);
  EXPECT_EQ(with_close.away, close_as_near.away);
  EXPECT_LT(with_close.away, alone.away - 0.02);
  EXPECT_GT(distance(with_close.at.at, Vec3{0.5, 0.5, 0}), with_close.away - 0.02 * Scene(close).patch.mean_edge_length());
}

}  // namespace
}  // namespace meshparticles::testing
