#include "particles/surface_voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace meshparticles {

double SurfaceVoronoi::cover() const { return largest_finite(distance); }

std::vector<SurfacePath> SurfaceVoronoi::neighbour_paths(const SurfaceMesh& mesh) const {
  // Every edge two regions share, once (from its end in the region of the
  // lower index), with the path through it.
  struct Through {
    SurfacePath path;
    VertexId v, w;  // v in a's region, w in b's
  };
  std::vector<Through> through;
  const auto& positions = mesh.positions();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    const std::uint32_t p = owner[v];
    if (p == kNoPoint) continue;
    for (const VertexId w : mesh.one_ring(v)) {
      const std::uint32_t q = owner[w];
      if (q == kNoPoint || q <= p) continue;
      const double edge = meshparticles::distance(positions[v], positions[w]);
      through.push_back({{p, q, double(distance[v]) + edge + double(distance[w]), 0.5 * (positions[v] + positions[w])},
                         v, w});
    }
  }
  // The shortest per pair; of equal ones, the first edge by its ends: the
  // same crossing on any machine.
  std::sort(through.begin(), through.end(), [](const Through& x, const Through& y) {
    return std::tie(x.path.a, x.path.b, x.path.length, x.v, x.w) <
           std::tie(y.path.a, y.path.b, y.path.length, y.v, y.w);
  });
  std::vector<SurfacePath> paths;
  for (const Through& t : through) {
    if (paths.empty() || paths.back().a != t.path.a || paths.back().b != t.path.b) paths.push_back(t.path);
  }
  return paths;
}

namespace {

// Point i's triangle's corner `c` at its straight distance from it, where
// that is nearer than what `voronoi` holds there or c has no point yet (of
// points equally near, the first seeded keeps it); whether i took it.
bool seed_corner(const SurfaceMesh& mesh, std::span<const SurfaceLocation> points, std::uint32_t i, VertexId c,
                 SurfaceVoronoi& voronoi) {
  const float d = float(distance(points[i].at, mesh.positions()[c]));
  if (d >= voronoi.distance[c] && voronoi.owner[c] != SurfaceVoronoi::kNoPoint) return false;
  voronoi.distance[c] = d;
  voronoi.owner[c] = i;
  return true;
}

}  // namespace

SurfaceVoronoi seeded_surface_voronoi(const SurfaceMesh& mesh, std::span<const SurfaceLocation> points,
                                      std::vector<VertexId>& seeds) {
  SurfaceVoronoi voronoi;
  voronoi.distance.assign(mesh.vertex_count(), std::numeric_limits<float>::infinity());
  voronoi.owner.assign(mesh.vertex_count(), SurfaceVoronoi::kNoPoint);
  seeds.clear();
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    for (const VertexId c : mesh.triangles()[points[i].triangle]) {
      if (voronoi.owner[c] == SurfaceVoronoi::kNoPoint) seeds.push_back(c);
      seed_corner(mesh, points, i, c, voronoi);
    }
  }
  return voronoi;
}

SurfaceVoronoi surface_voronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                               std::span<const SurfaceLocation> points, SolverScratch& scratch) {
  std::vector<VertexId> seeds;
  SurfaceVoronoi voronoi = seeded_surface_voronoi(mesh, points, seeds);
  std::vector<std::uint32_t> seed_owners;
  for (const VertexId c : seeds) seed_owners.push_back(voronoi.owner[c]);
  std::vector<VertexId> lowered;
  std::vector<std::uint32_t> lowered_owners;
  if (!seeds.empty()) {
    solver.lower_nearest_from(seeds, seed_owners, voronoi.distance, scratch, lowered, lowered_owners);
  }
  for (std::size_t k = 0; k < lowered.size(); ++k) voronoi.owner[lowered[k]] = lowered_owners[k];
  return voronoi;
}

MovedPointsReseeded reseed_moved_points(const SurfaceMesh& mesh, std::span<const SurfaceLocation> points,
                                        std::span<const char> moved, SurfaceVoronoi& cells) {
  MovedPointsReseeded reseeded;
  for (VertexId v = 0; v < cells.owner.size(); ++v) {
    if (cells.owner[v] == SurfaceVoronoi::kNoPoint || !moved[cells.owner[v]]) continue;
    cells.distance[v] = std::numeric_limits<float>::infinity();
    cells.owner[v] = SurfaceVoronoi::kNoPoint;
    reseeded.emptied.push_back(v);
  }
  // The moved points' corners, as seeded_surface_voronoi seeds them.
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (!moved[i]) continue;
    for (const VertexId c : mesh.triangles()[points[i].triangle]) {
      if (!seed_corner(mesh, points, i, c, cells)) continue;
      reseeded.corners.push_back(c);
      reseeded.corner_points.push_back(i);
    }
  }
  return reseeded;
}

void update_surface_voronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                            std::span<const SurfaceLocation> points, std::span<const char> moved,
                            SurfaceVoronoi& cells, SolverScratch& scratch) {
  MovedPointsReseeded reseeded = reseed_moved_points(mesh, points, moved, cells);
  std::vector<VertexId>& sources = reseeded.corners;
  std::vector<std::uint32_t>& source_owners = reseeded.corner_points;
  // Then the rims, each vertex from the point that holds it now (a corner
  // just seeded: its new point).
  for (const VertexId v : reseeded.emptied) {
    for (const VertexId w : mesh.one_ring(v)) {
      if (cells.owner[w] == SurfaceVoronoi::kNoPoint) continue;
      sources.push_back(w);
      source_owners.push_back(cells.owner[w]);
    }
  }
  if (sources.empty()) return;
  std::vector<VertexId> lowered;
  std::vector<std::uint32_t> lowered_owners;
  solver.lower_nearest_from(sources, source_owners, cells.distance, scratch, lowered, lowered_owners);
  for (std::size_t k = 0; k < lowered.size(); ++k) cells.owner[lowered[k]] = lowered_owners[k];
}

}  // namespace meshparticles
