#include "particles/widest_hole.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "geodesics/point_source_update.hpp"

namespace meshparticles {

namespace {

// Points along a triangle's edge at most (a triangle 60 steps long is sampled more coarsely).
constexpr int kMostSteps = 60;

// A point's way to `vertex` (`to_vertex` along the surface) over the
// straight line, less the marching's own excess (kPathSlack), at least 1.
double stretch(const Vec3& vertex, double to_vertex, const Vec3& source) {
  const double straight = distance(vertex, source);
  return straight > 0 ? std::max(1.0, to_vertex / straight - kPathSlack) : 1.0;
}

struct PointDistance {
  std::uint32_t owner = SurfaceVoronoi::kNoPoint;
  double away = std::numeric_limits<double>::infinity();
};

// What a triangle's points are measured against: every vertex of its
// corners' rings held by a point (the nearest may own no corner where three
// regions meet), with that point's stretch there (its way to the vertex
// over the straight line: 1 on a plane, more round a finger; less the
// marching's own excess, kPathSlack), and the points in the triangles
// around its corners (one may own no vertex at all, each nearer another,
// and still be the nearest: within a ring the straight line is the way).
struct Candidates {
  struct RingVertex {
    VertexId vertex;
    std::uint32_t owner;
    double stretch;
  };
  std::vector<RingVertex> ring;
  std::vector<std::uint32_t> nearby;
};

void gather_candidates(const SurfaceMesh& mesh, const VertexTriangles& rings, const Triangle& corners,
                       const SurfaceVoronoi& diagram, std::span<const SurfaceLocation> points,
                       const std::vector<std::vector<std::uint32_t>>& around, Candidates& candidates) {
  const auto& positions = mesh.positions();
  candidates.ring.clear();
  candidates.nearby.clear();
  for (const VertexId c : corners) {
    for (const std::uint32_t ring_triangle : rings.around(c)) {
      for (const VertexId v : mesh.triangles()[ring_triangle]) {
        const std::uint32_t owner = diagram.owner[v];
        if (owner == SurfaceVoronoi::kNoPoint) continue;
        const auto seen = [&](const Candidates::RingVertex& r) { return r.vertex == v; };
        if (std::any_of(candidates.ring.begin(), candidates.ring.end(), seen)) continue;
        candidates.ring.push_back({v, owner, stretch(positions[v], diagram.distance[v], points[owner].at)});
      }
    }
    for (const std::uint32_t k : around[c]) {
      if (std::find(candidates.nearby.begin(), candidates.nearby.end(), k) == candidates.nearby.end()) {
        candidates.nearby.push_back(k);
      }
    }
  }
}

// `point`'s distance from the diagram's points, as widest_hole says: fast
// marching's update from two corners one point holds, each ring vertex's
// point's stretched straight line within what the vertex bounds, and the
// straight line to each point nearby.
PointDistance distance_at(const SurfaceMesh& mesh, const Triangle& corners, const Vec3& point,
                          const SurfaceVoronoi& diagram, std::span<const SurfaceLocation> points,
                          const Candidates& candidates) {
  const auto& positions = mesh.positions();
  PointDistance nearest;
  const auto take = [&](std::uint32_t owner, double away) {
    if (away < nearest.away || (away == nearest.away && owner < nearest.owner)) nearest = {owner, away};
  };
  for (std::size_t c = 0; c < 3; ++c) {
    const VertexId x = corners[c], y = corners[(c + 1) % 3];
    if (diagram.owner[x] != SurfaceVoronoi::kNoPoint && diagram.owner[y] == diagram.owner[x]) {
      take(diagram.owner[x],
           point_source_update(point_frame(positions[x], positions[y], point), diagram.distance[x], diagram.distance[y]));
    }
  }
  for (const Candidates::RingVertex& r : candidates.ring) {
    const double to_vertex = diagram.distance[r.vertex], from_vertex = distance(point, positions[r.vertex]);
    const double straight = distance(point, points[r.owner].at);
    take(r.owner, std::min(std::max(r.stretch * straight, std::max(straight, to_vertex - from_vertex)), to_vertex + from_vertex));
  }
  for (const std::uint32_t k : candidates.nearby) take(k, distance(point, points[k].at));
  return nearest;
}

}  // namespace

WidestHole widest_hole(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceVoronoi& diagram,
                       std::span<const SurfaceLocation> points, double step) {
  const auto& positions = mesh.positions();
  const auto& triangles = mesh.triangles();
  // The room each triangle leaves for a hole: no point of it is measured
  // farther than a corner's point's stretched straight line to the
  // triangle's farthest corner (the line's length is convex) or than the
  // corner's own distance, whichever is more.
  std::vector<double> room(triangles.size(), -std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const Triangle& t = triangles[k];
    double least = std::numeric_limits<double>::infinity();
    for (const VertexId c : t) {
      const std::uint32_t owner = diagram.owner[c];
      if (owner == SurfaceVoronoi::kNoPoint) continue;
      const Vec3 source = points[owner].at;
      double farthest = 0;
      for (const VertexId corner : t) farthest = std::max(farthest, distance(positions[corner], source));
      const double bound = std::max(stretch(positions[c], diagram.distance[c], source) * farthest, double(diagram.distance[c]));
      least = std::min(least, bound * (1 + 1e-9));
    }
    if (std::isfinite(least)) room[k] = least;
  }
  std::vector<std::uint32_t> order(triangles.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return room[a] > room[b] || (room[a] == room[b] && a < b);
  });
  std::vector<std::vector<std::uint32_t>> around(mesh.vertex_count());  // the points in each vertex's triangles
  for (std::uint32_t k = 0; k < points.size(); ++k) {
    for (const VertexId c : triangles[points[k].triangle]) around[c].push_back(k);
  }
  WidestHole widest;
  std::uint32_t widest_triangle = 0;
  Candidates candidates;
  for (const std::uint32_t k : order) {
    if (!std::isfinite(room[k]) || (widest.owner != SurfaceVoronoi::kNoPoint && room[k] < widest.away)) break;
    const Triangle& t = triangles[k];
    const Vec3 a = positions[t[0]], ab = positions[t[1]] - a, ac = positions[t[2]] - a;
    const double longest = std::max({norm(ab), norm(ac), norm(ac - ab)});
    const int parts = std::clamp(int(std::ceil(longest / step)), 1, kMostSteps);
    gather_candidates(mesh, rings, t, diagram, points, around, candidates);
    for (int i = 0; i <= parts; ++i) {
      for (int j = 0; i + j <= parts; ++j) {
        const double u = double(i) / parts, v = double(j) / parts;
        const Vec3 point = a + u * ab + v * ac;
        const PointDistance here = distance_at(mesh, t, point, diagram, points, candidates);
        if (here.owner == SurfaceVoronoi::kNoPoint) continue;
        const bool wider = widest.owner == SurfaceVoronoi::kNoPoint || here.away > widest.away ||
                           (here.away == widest.away && k < widest_triangle);
        if (!wider) continue;
        widest = {SurfaceLocation{k, {1 - u - v, u, v}, point}, here.owner, here.away};
        widest_triangle = k;
      }
    }
  }
  return widest;
}

}  // namespace meshparticles
