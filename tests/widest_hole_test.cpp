// The widest hole between the vertices: on a plane, where the way along
// the surface is the straight line, it must agree with the straight
// distance from the nearest point, found by brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "mesh/vertex_triangles.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/widest_hole.hpp"
#include "square_grid.hpp"

namespace meshparticles::testing {
namespace {

double straight_cover(const std::vector<SurfaceLocation>& points, double step) {
  double widest = 0;
  for (double x = 0; x <= 1 + 1e-12; x += step) {
    for (double y = 0; y <= 1 + 1e-12; y += step) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const SurfaceLocation& p : points) nearest = std::min(nearest, distance(p.at, {x, y, 0}));
      widest = std::max(widest, nearest);
    }
  }
  return widest;
}

// Points about evenly spread over a coarse grid (a 5 x 5 grid of cells'
// centres, each moved at random by up to 0.3 of its cell: 4 vertices to a
// point, as on FAUST's people at n = 1,024, so that some own no vertex and
// holes lie inside triangles whose corners three points own): the hole
// found is where it is said to be, as far as it is said to be, and within
// a sample step of the widest by brute force.
TEST(WidestHole, OnAPlaneItIsTheStraightCoverBetweenTheVertices) {
  const SurfaceMesh square = square_grid(10);
  const VertexTriangles rings = vertex_triangles(square.triangles(), square.vertex_count());
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(square);
  std::uint64_t state = 7;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  };
  for (int set = 0; set < 10; ++set) {
    std::vector<SurfaceLocation> points;
    for (int k = 0; k < 25; ++k) {
      const double x = 0.2 * (k % 5 + 0.5 + 0.6 * (next() - 0.5)), y = 0.2 * (k / 5 + 0.5 + 0.6 * (next() - 0.5));
      points.push_back(*nearest.find({x, y, 0}));
    }
    SolverScratch scratch;
    const SurfaceVoronoi diagram = surface_voronoi(square, *solver, points, scratch);
    const WidestHole hole = widest_hole(square, rings, diagram, points, 0.01);
    EXPECT_NEAR(hole.away, straight_cover(points, 0.002), 0.006) << set;
    ASSERT_LT(hole.owner, points.size());
    EXPECT_NEAR(distance(hole.at.at, points[hole.owner].at), hole.away, 1e-3) << set;
    for (const SurfaceLocation& p : points) EXPECT_GE(distance(p.at, hole.at.at), hole.away - 1e-3) << set;
  }
}

// A point inside a triangle whose corners other points hold owns no vertex
// of the diagram; the hole it fills is filled all the same (here one at
// every vertex and one at every triangle's centroid).
TEST(WidestHole, APointOwningNoVertexStillFillsItsHole) {
  const SurfaceMesh square = square_grid(2);
  const VertexTriangles rings = vertex_triangles(square.triangles(), square.vertex_count());
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(square);
  std::vector<SurfaceLocation> points;
  for (const Vec3& corner : square.positions()) points.push_back(*nearest.find(corner));
  const std::size_t at_vertices = points.size();
  for (const Triangle& t : square.triangles()) {
    const auto& p = square.positions();
    points.push_back(*nearest.find((1.0 / 3) * (p[t[0]] + p[t[1]] + p[t[2]])));
  }
  SolverScratch scratch;
  const SurfaceVoronoi diagram = surface_voronoi(square, *solver, points, scratch);
  for (const std::uint32_t owner : diagram.owner) EXPECT_LT(owner, at_vertices);
  const WidestHole hole = widest_hole(square, rings, diagram, points, 0.01);
  EXPECT_NEAR(hole.away, straight_cover(points, 0.002), 0.006);
}

}  // namespace
}  // namespace meshparticles::testing
