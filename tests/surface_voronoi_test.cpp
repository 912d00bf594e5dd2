// The neighbours of the particles' geodesic Voronoi diagram
// (particles/surface_voronoi): each pair of regions that share an edge
// once, with the shortest path through a shared edge, and where that path
// crosses their border (the evening's moves read it: particles/
// local_farthest_points), checked against every shared edge by brute force.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "particles/surface_voronoi.hpp"
#include "square_grid.hpp"

namespace meshparticles::testing {
namespace {

TEST(SurfaceVoronoi, NeighbourPathsAreTheShortestThroughTheBorderAndCrossItThere) {
  const SurfaceMesh square = square_grid(12);
  const auto solver = make_geodesic_solver(square, GeodesicMethod::fast_marching);
  const NearestSurfacePoint nearest(square);
  std::vector<SurfaceLocation> points;
  for (int k = 0; k < 16; ++k) {
    const double x = 0.25 * (k % 4 + 0.5) + 0.03 * (k % 3 - 1), y = 0.25 * (k / 4 + 0.5) + 0.02 * (k % 5 - 2);
    points.push_back(*nearest.find({x, y, 0}));
  }
  SolverScratch scratch;
  const SurfaceVoronoi diagram = surface_voronoi(square, *solver, points, scratch);
  // Per pair of regions, the shortest path through each edge they share.
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> shortest;
  const auto& at = square.positions();
  for (VertexId v = 0; v < square.vertex_count(); ++v) {
    for (const VertexId w : square.one_ring(v)) {
      const std::uint32_t a = diagram.owner[v], b = diagram.owner[w];
      if (a >= b || b == SurfaceVoronoi::kNoPoint) continue;
      const double length = diagram.distance[v] + distance(at[v], at[w]) + diagram.distance[w];
      auto [it, added] = shortest.try_emplace({a, b}, length);
      if (!added) it->second = std::min(it->second, length);
    }
  }
  const std::vector<SurfacePath> paths = diagram.neighbour_paths(square);
  ASSERT_EQ(paths.size(), shortest.size());
  for (const SurfacePath& path : paths) {
    ASSERT_LT(path.a, path.b);
    ASSERT_TRUE(shortest.contains({path.a, path.b}));
    EXPECT_DOUBLE_EQ(path.length, shortest.at({path.a, path.b}));
    // The crossing is the middle of a shared edge that path runs through.
    bool found = false;
    for (VertexId v = 0; v < square.vertex_count() && !found; ++v) {
      for (const VertexId w : square.one_ring(v)) {
        if (diagram.owner[v] != path.a || diagram.owner[w] != path.b) continue;
        const double length = diagram.distance[v] + distance(at[v], at[w]) + diagram.distance[w];
        found = found || (length == path.length && distance(0.5 * (at[v] + at[w]), path.crossing) < 1e-12);
      }
    }
    EXPECT_TRUE(found) << path.a << " " << path.b;
  }
}

}  // namespace
}  // namespace meshparticles::testing
