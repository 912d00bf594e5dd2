#pragma once
// The geodesic Voronoi diagram of points anywhere on a surface (each in a
// triangle, off the vertices), sampled at the mesh's vertices: every
// vertex's distance to its nearest point and which point that is, from one
// fast-marching solve seeded at each point's triangle corners.
//
// It answers what straight lines cannot on real shapes: two points are
// neighbours *on the surface* exactly when their regions share an edge (the
// restricted Delaunay graph), so a pair facing each other across a gap in
// the air (an ear and the head, two legs, the sides of a fold) never is;
// and its largest distance is the geodesic covering radius.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/surface_walk.hpp"

namespace meshparticles {

// The path d(v) + |vw| + d(w) through the best edge between two regions is
// longer than the geodesic by up to a few per cent of a spacing (the edge
// crosses the path at an angle): a pair's stretch (path over straight line)
// is that ratio less this, and 1 where that is smaller (smooth neighbours,
// whose straight line is the geodesic to within the surface's curvature).
inline constexpr double kPathSlack = 0.1;

// Two neighbours on the surface and the length of the shortest path between
// them through an edge their regions share: d(v) + |vw| + d(w).
struct SurfacePath {
  std::uint32_t a = 0, b = 0;  // a < b
  double length = 0;
  Vec3 crossing;  // the middle of that edge
};

struct SurfaceVoronoi {
  static constexpr std::uint32_t kNoPoint = 0xFFFFFFFFu;
  std::vector<float> distance;        // per vertex, to its nearest point (+inf in a component with none)
  std::vector<std::uint32_t> owner;   // per vertex: that point, kNoPoint where none

  // The largest finite distance: the covering radius.
  double cover() const;
  // Every pair of neighbours once, sorted by (a, b), with its shortest path.
  std::vector<SurfacePath> neighbour_paths(const SurfaceMesh& mesh) const;
};

// The diagram's start, shared by the host (surface_voronoi) and the device
// (device_surface_voronoi): each point's triangle corners at their straight
// distance from it, a corner shared by several points' triangles going to
// the nearest (ties: the first point); every other vertex +inf, no point.
// `seeds`: the corners set, each once, in the order first set.
SurfaceVoronoi seeded_surface_voronoi(const SurfaceMesh& mesh, std::span<const SurfaceLocation> points,
                                      std::vector<VertexId>& seeds);

// The diagram of `points` on `mesh`, measured by `solver` (built for `mesh`):
// each point starts its triangle's corners at their straight distance from
// it (a vertex shared by several points' triangles goes to the nearest).
SurfaceVoronoi surface_voronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                               std::span<const SurfaceLocation> points, SolverScratch& scratch);

// The first step of bringing a diagram up to date after points moved,
// shared by the host (update_surface_voronoi) and the device
// (DeviceSurfaceVoronoi::update): the regions of the points flagged in
// `moved` emptied (+inf, no point), then each moved point's new triangle's
// corners seeded where it is nearer, as seeded_surface_voronoi seeds them.
struct MovedPointsReseeded {
  std::vector<VertexId> emptied;
  // Each corner a moved point took, in the order taken, with that point (a
  // corner taken twice is listed twice, the later point the nearer).
  std::vector<VertexId> corners;
  std::vector<std::uint32_t> corner_points;
};
MovedPointsReseeded reseed_moved_points(const SurfaceMesh& mesh, std::span<const SurfaceLocation> points,
                                        std::span<const char> moved, SurfaceVoronoi& cells);

// Brings `cells`, the diagram of `points` before those flagged in `moved`
// moved, up to date: the regions the moved points held are emptied and
// filled again from their rims (each rim vertex from its own point, at its
// distance), and each moved point seeds its new triangle's corners where
// it is nearer, in one march that lowers wherever it finds a nearer point.
// At a cost in proportion to those regions, not the mesh: what
// surface_voronoi gives anew, up to the order fast marching accepts
// vertices in along the borders.
void update_surface_voronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                            std::span<const SurfaceLocation> points, std::span<const char> moved,
                            SurfaceVoronoi& cells, SolverScratch& scratch);

}  // namespace meshparticles
