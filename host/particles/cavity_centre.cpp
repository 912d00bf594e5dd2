#include "particles/cavity_centre.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace meshparticles {

namespace {

constexpr float kBeyond = std::numeric_limits<float>::infinity();

// The centre of the circle through a, b and c; false when they are on a line.
bool circumcentre(const PlanarSource& a, const PlanarSource& b, const PlanarSource& c, double& x, double& y) {
  const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  if (std::abs(d) < 1e-300) return false;
  const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
  x = (a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d;
  y = (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d;
  return true;
}

double nearest_source(const std::vector<PlanarSource>& sources, double x, double y) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const PlanarSource& s : sources) nearest = std::min(nearest, s.distance_to(x, y));
  return nearest;
}

// The sources of the triangle of `frame`: each listed particle whose ball
// reaches all three corners.
void planar_sources(const TriangleFrame& frame, const Triangle& corners, CavityScratch& s) {
  const std::size_t rows = s.vertices.size();
  s.planar.clear();
  for (std::size_t k = 0; k < s.sources.size(); ++k) {
    const float* column = s.table.data() + k * rows;
    std::array<double, 3> d{};
    bool reached = true;
    for (int c = 0; c < 3; ++c) {
      d[c] = column[s.row[corners[c]]];
      reached = reached && std::isfinite(d[c]);
    }
    if (reached) s.planar.push_back(planar_source(frame, d));
  }
}

// The triangles of the cavity and their corners, each corner given its row
// and its way to the farther other corner of its triangle.
void gather(const SurfaceMesh& mesh, const VertexTriangles& rings, const Cavity& cavity, CavityScratch& s) {
  s.triangles.clear();
  for (const VertexId v : cavity.region) {
    for (const std::uint32_t t : rings.around(v)) s.triangles.push_back(t);
  }
  s.triangles.push_back(cavity.at.triangle);
  std::sort(s.triangles.begin(), s.triangles.end());
  s.triangles.erase(std::unique(s.triangles.begin(), s.triangles.end()), s.triangles.end());
  if (s.row.empty()) s.row.assign(mesh.vertex_count(), -1);
  s.vertices.clear();
  s.ways.clear();
  const auto& positions = mesh.positions();
  for (const std::uint32_t t : s.triangles) {
    const Triangle& c = mesh.triangles()[t];
    for (int k = 0; k < 3; ++k) {
      s.ways.push_back(std::max(distance(positions[c[k]], positions[c[(k + 1) % 3]]),
                                distance(positions[c[k]], positions[c[(k + 2) % 3]])));
      if (s.row[c[k]] >= 0) continue;
      s.row[c[k]] = std::int32_t(s.vertices.size());
      s.vertices.push_back(c[k]);
    }
  }
  s.sources.clear();
  s.table.clear();
  s.nearest.assign(s.vertices.size(), kBeyond);
}

// Source `particle` added: its column of the table (its ball's distances at
// the gathered vertices), and each row's nearest lowered.
void add_source(std::uint32_t particle, const std::vector<ParticleBall>& balls, CavityScratch& s) {
  const std::size_t rows = s.vertices.size();
  s.sources.push_back(particle);
  s.table.resize(s.sources.size() * rows, kBeyond);
  float* column = s.table.data() + (s.sources.size() - 1) * rows;
  for (const auto& [v, d] : balls[particle]) {
    if (s.row[v] >= 0) column[s.row[v]] = d;
  }
  for (std::size_t r = 0; r < rows; ++r) s.nearest[r] = std::min(s.nearest[r], column[r]);
}

// Per gathered triangle, a bound on how far any of its points is from the
// sources: no point of a triangle is farther than a corner's nearest source
// plus the way to the farthest other corner. In s.order, in s.triangles' order.
void bound_triangles(const SurfaceMesh& mesh, CavityScratch& s) {
  s.order.clear();
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const Triangle& c = mesh.triangles()[s.triangles[i]];
    double bound = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) bound = std::min(bound, s.nearest[s.row[c[k]]] + s.ways[3 * i + std::size_t(k)]);
    s.order.emplace_back(bound, s.triangles[i]);
  }
}

// The farthest point of the gathered triangles from `s.sources`: the
// triangles searched in the order of their bounds (bound_triangles, for
// these sources), until none left can hold a farther point.
CavityCentre widest_from_sources(const SurfaceMesh& mesh, const SurfaceLocation& at, CavityScratch& s) {
  std::sort(s.order.begin(), s.order.end(),
            [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
  CavityCentre widest;
  const TriangleFrame own = triangle_frame(mesh, at.triangle);
  if (!own.degenerate()) {
    planar_sources(own, mesh.triangles()[at.triangle], s);
    const auto [x, y] = own.plane(at.at);
    widest.here = nearest_source(s.planar, x, y);
  }
  for (const auto& [bound, triangle] : s.order) {
    if (bound <= widest.away) break;
    const std::uint32_t t = triangle;  // a copy: clang 14 lets no lambda capture a structured binding
    const TriangleFrame f = triangle_frame(mesh, t);
    if (f.degenerate()) continue;
    planar_sources(f, mesh.triangles()[t], s);
    if (s.planar.empty()) continue;
    // Only the sources within two longest edges of the nearest at the
    // centroid can be the nearest anywhere in the triangle.
    const double gx = (f.b + f.cx) / 3, gy = f.cy / 3;
    const double longest = std::max({f.b, planar_distance(f.cx, f.cy), planar_distance(f.cx - f.b, f.cy)});
    const double nearest = nearest_source(s.planar, gx, gy);
    s.near.clear();
    for (const PlanarSource& q : s.planar) {
      if (q.distance_to(gx, gy) <= nearest + 2 * longest) s.near.push_back(q);
    }
    const auto consider = [&](double x, double y) {
      if (!f.holds(x, y)) return;
      const double away = nearest_source(s.near, x, y);
      if (away > widest.away) {
        widest.away = away;
        widest.at = {t, f.weights(x, y), f.point(x, y)};
      }
    };
    const double corner[3][2] = {{0, 0}, {f.b, 0}, {f.cx, f.cy}};
    for (const auto& c : corner) consider(c[0], c[1]);
    for (std::size_t a = 0; a < s.near.size(); ++a) {
      for (std::size_t b = a + 1; b < s.near.size(); ++b) {
        // Where the line of points equally near a and b (straight lines:
        // the offsets are left out of where, not of how far) crosses an edge.
        const PlanarSource &p = s.near[a], &q = s.near[b];
        const double ex = q.x - p.x, ey = q.y - p.y;
        const double half = (q.x * q.x + q.y * q.y - p.x * p.x - p.y * p.y) / 2;
        for (int e = 0; e < 3; ++e) {
          const double* from = corner[e];
          const double* to = corner[(e + 1) % 3];
          const double dx = to[0] - from[0], dy = to[1] - from[1];
          const double slope = dx * ex + dy * ey;
          if (slope == 0) continue;
          const double along = (half - from[0] * ex - from[1] * ey) / slope;
          if (along > 0 && along < 1) consider(from[0] + along * dx, from[1] + along * dy);
        }
        for (std::size_t c = b + 1; c < s.near.size(); ++c) {
          double x = 0, y = 0;
          if (circumcentre(p, q, s.near[c], x, y)) consider(x, y);
        }
      }
    }
  }
  return widest;
}

}  // namespace

CavityCentre cavity_centre(const SurfaceMesh& mesh, const VertexTriangles& rings, const Cavity& cavity,
                           const std::vector<SurfaceLocation>& points, const std::vector<ParticleBall>& balls,
                           CavityScratch& s) {
  gather(mesh, rings, cavity, s);
  for (const std::uint32_t k : cavity.near) add_source(k, balls, s);
  // A particle further out is d >= its straight line >= that to `at` less
  // the farthest corner's from `at`. No point of the cavity is farther from
  // the near particles than the widest triangle's bound; one no nearer than
  // that to every point changes nothing, and is left out (the widest gap
  // found with the near particles alone, a second search, left out the
  // same particles and a few more: the same bytes on the 92 corpus runs).
  // (A triangle no near particle reaches at any corner holds no reading:
  // its bound, infinite, bounds nothing found.)
  bound_triangles(mesh, s);
  double widest_bound = -std::numeric_limits<double>::infinity();
  for (const auto& [bound, triangle] : s.order) {
    if (std::isfinite(bound)) widest_bound = std::max(widest_bound, bound);
  }
  double reach = 0;
  for (const VertexId v : s.vertices) reach = std::max(reach, distance(cavity.at.at, mesh.positions()[v]));
  const std::size_t near_count = s.sources.size();
  for (const std::uint32_t k : cavity.further) {
    if (distance(cavity.at.at, points[k].at) - reach <= widest_bound) add_source(k, balls, s);
  }
  if (s.sources.size() > near_count) bound_triangles(mesh, s);
  const CavityCentre widest = widest_from_sources(mesh, cavity.at, s);
  for (const VertexId v : s.vertices) s.row[v] = -1;
  return widest;
}

}  // namespace meshparticles
