#include "geodesics/point_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace meshparticles {

namespace {

// The angle between u and v, in [0, pi].
double angle_between(const Vec3& u, const Vec3& v) { return std::atan2(norm(cross(u, v)), dot(u, v)); }

// An edge of a corner's fan unfolded: its direction's angle from the
// point's, and its length.
struct UnfoldedEdge {
  double angle, length;
};

// Whether the segment from the point (at `from`, on the x-axis) to
// `to` crosses every unfolded edge within its length (a little slack for
// rounding: a line through a vertex).
bool crosses_within(const std::vector<UnfoldedEdge>& edges, double from, double to_x, double to_y) {
  constexpr double kSlack = 1e-9;
  const double dx = to_x - from, dy = to_y;
  for (const UnfoldedEdge& e : edges) {
    const double ux = std::cos(e.angle), uy = std::sin(e.angle);
    const double denominator = ux * dy - uy * dx;  // cross(u, to - from)
    if (denominator == 0) return false;
    const double t = uy * from / denominator;  // -cross(u, from) / cross(u, to - from)
    const double along = ux * (from + t * dx) + uy * (t * dy);
    if (along > e.length * (1 + kSlack)) return false;
  }
  return true;
}

void keep_nearer(VertexId v, double d, PointSeeds& seeds) {
  const auto found = std::find(seeds.vertices.begin(), seeds.vertices.end(), v);
  if (found == seeds.vertices.end()) {
    seeds.vertices.push_back(v);
    seeds.distances.push_back(d);
    return;
  }
  double& kept = seeds.distances[std::size_t(found - seeds.vertices.begin())];
  kept = std::min(kept, d);
}

// The triangle other than `current` around `corner` that holds `edge_end`:
// none where there is none or more than one (a boundary, or an edge of
// more than two triangles).
std::int64_t across(const SurfaceMesh& mesh, const VertexTriangles& rings, VertexId corner, VertexId edge_end,
                    std::uint32_t current) {
  std::int64_t found = -1;
  for (const std::uint32_t t : rings.around(corner)) {
    if (t == current) continue;
    const Triangle& c = mesh.triangles()[t];
    if (std::find(c.begin(), c.end(), edge_end) == c.end()) continue;
    if (found >= 0) return -1;
    found = t;
  }
  return found;
}

// The vertices of `corner`'s fan reached from the point by unfolding the
// triangles one after another from the edge to `first`, away from the
// point's triangle, while the way turns less than half a turn about the
// corner.
void unfold_fan(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceLocation& point, VertexId corner,
                VertexId first, PointSeeds& seeds) {
  const auto& at = mesh.positions();
  const Vec3 to_point = point.at - at[corner];
  const double from = norm(to_point);  // the point, unfolded, at (from, 0)
  std::vector<UnfoldedEdge> edges{{angle_between(to_point, at[first] - at[corner]), distance(at[first], at[corner])}};
  std::uint32_t current = point.triangle;
  VertexId edge_end = first;
  for (std::size_t step = 0; step < rings.around(corner).size(); ++step) {
    const std::int64_t next = across(mesh, rings, corner, edge_end, current);
    if (next < 0 || std::uint32_t(next) == point.triangle) return;
    const Triangle& t = mesh.triangles()[std::size_t(next)];
    VertexId third = t[0];
    for (const VertexId c : t) {
      if (c != corner && c != edge_end) third = c;
    }
    const double angle =
        edges.back().angle + angle_between(at[edge_end] - at[corner], at[third] - at[corner]);
    if (angle >= std::numbers::pi) return;
    const double length = distance(at[third], at[corner]);
    const double x = length * std::cos(angle), y = length * std::sin(angle);
    if (!crosses_within(edges, from, x, y)) return;
    keep_nearer(third, std::hypot(x - from, y), seeds);
    edges.push_back({angle, length});
    edge_end = third;
    current = std::uint32_t(next);
  }
}

}  // namespace

void point_seeds(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceLocation& point,
                 PointSeeds& seeds) {
  seeds.vertices.clear();
  seeds.distances.clear();
  const Triangle& corners = mesh.triangles()[point.triangle];
  for (const VertexId c : corners) keep_nearer(c, distance(point.at, mesh.positions()[c]), seeds);
  for (int k = 0; k < 3; ++k) {
    unfold_fan(mesh, rings, point, corners[k], corners[(k + 1) % 3], seeds);
    unfold_fan(mesh, rings, point, corners[k], corners[(k + 2) % 3], seeds);
  }
}

}  // namespace meshparticles
