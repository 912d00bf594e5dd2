#include "geodesics/triangle_stencils.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "common/compressed_rows.hpp"
#include "common/parallel_for.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

namespace {

struct Point2 {
  double x, y;
};
Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
double length(Point2 a) { return std::sqrt(dot(a, a)); }

// The point at distances r_p from p and r_q from q, on the side of line pq
// away from `away`.
Point2 place_opposite(Point2 p, Point2 q, double r_p, double r_q, Point2 away) {
  const Point2 pq = q - p;
  const double base = length(pq);
  const double along = (r_p * r_p - r_q * r_q + base * base) / (2 * base);
  const double height = std::sqrt(std::max(0.0, r_p * r_p - along * along));
  const Point2 unit{pq.x / base, pq.y / base};
  const Point2 normal{-unit.y, unit.x};
  const double side = cross(pq, away - p) > 0 ? -1.0 : 1.0;
  return {p.x + along * unit.x + side * height * normal.x, p.y + along * unit.y + side * height * normal.y};
}

// The frame of C seen from X and Y, all given as points in one plane.
PlanarFrame frame_of(Point2 pc, Point2 px, Point2 py) {
  const Point2 axis = py - px;
  const double base = length(axis);
  const Point2 unit{axis.x / base, axis.y / base};
  const Point2 rel = pc - px;
  return {float(base), float(dot(rel, unit)), float(-std::abs(cross(unit, rel)))};  // C below the x-axis
}

// Lays a triangle with the given side lengths into the plane: X at the
// origin, Y on the x-axis, C below.
PlanarFrame frame_of_lengths(double xy, double xc, double yc) {
  const double c_x = (xc * xc - yc * yc + xy * xy) / (2 * xy);
  return {float(xy), float(c_x), float(-std::sqrt(std::max(0.0, xc * xc - c_x * c_x)))};
}

// The triangles on edge pq, in increasing order: the first two, and how
// many there are.
struct EdgeTriangles {
  std::size_t count = 0;
  std::array<std::uint32_t, 2> first{};
};
EdgeTriangles triangles_on_edge(const VertexTriangles& around, const std::vector<Triangle>& triangles, VertexId p,
                                VertexId q) {
  EdgeTriangles found;
  for (const std::uint32_t t : around.around(p)) {
    if (triangles[t][0] != q && triangles[t][1] != q && triangles[t][2] != q) continue;
    if (found.count < 2) found.first[found.count] = t;
    ++found.count;
  }
  return found;
}

VertexId third_vertex(const Triangle& t, VertexId a, VertexId b) {
  for (VertexId v : t) {
    if (v != a && v != b) return v;
  }
  return t[0];
}

}  // namespace

TriangleStencils build_triangle_stencils(const SurfaceMesh& mesh, unsigned threads) {
  const auto& positions = mesh.positions();
  const auto& triangles = mesh.triangles();
  const VertexTriangles around = vertex_triangles(triangles, mesh.vertex_count());
  const auto length3 = [&](VertexId a, VertexId b) { return distance(positions[a], positions[b]); };

  // Listed in triangle order whatever the threads: corner k of triangle t at
  // 3t + k, the virtual updates piece by piece, the pieces joined in order.
  std::vector<std::pair<VertexId, TriangleAtVertex>> triangle_records(3 * triangles.size());
  constexpr std::size_t kPieceTriangles = 16384;
  std::vector<std::vector<std::pair<VertexId, VirtualUpdate>>> virtual_pieces(
      piece_count(triangles.size(), kPieceTriangles));
  constexpr int kMaxUnfoldings = 10;
  for_each_piece(triangles.size(), kPieceTriangles, threads, [&](std::size_t piece, std::size_t from, std::size_t to) {
    std::vector<std::pair<VertexId, VirtualUpdate>>& virtual_records = virtual_pieces[piece];
    // Both orders (C from X,Y and from Y,X): either corner may be accepted last.
    const auto add_virtual = [&](VertexId c, VertexId x, VertexId y, Point2 pc, Point2 px, Point2 py) {
      virtual_records.push_back({x, {c, y, frame_of(pc, px, py)}});
      virtual_records.push_back({y, {c, x, frame_of(pc, py, px)}});
    };
    for (std::uint32_t t = std::uint32_t(from); t < to; ++t) {
      for (int k = 0; k < 3; ++k) {
        const VertexId c = triangles[t][k], a = triangles[t][(k + 1) % 3], b = triangles[t][(k + 2) % 3];
        const double ca = length3(c, a), cb = length3(c, b), ab = length3(a, b);
        triangle_records[3 * std::size_t(t) + k] = {
            c, {a, b, frame_of_lengths(ca, cb, ab), frame_of_lengths(cb, ca, ab)}};

        // C's corner in the plane: C at the origin, A on the x-axis, B above.
        const Vec3 ca3 = positions[a] - positions[c], cb3 = positions[b] - positions[c];
        const double angle = std::atan2(norm(meshparticles::cross(ca3, cb3)), meshparticles::dot(ca3, cb3));
        if (angle <= std::numbers::pi / 2) continue;
        const Point2 pc{0, 0}, pa{ca, 0}, pb{cb * std::cos(angle), cb * std::sin(angle)};

        // Unfold across the far edge until a vertex lands inside C's angle.
        VertexId p = a, q = b;
        Point2 pp = pa, pq = pb, previous = pc;
        std::uint32_t current = t;
        for (int step = 0; step < kMaxUnfoldings; ++step) {
          const EdgeTriangles sharing = triangles_on_edge(around, triangles, p, q);
          if (sharing.count != 2) break;  // reached the boundary (or a non-manifold edge)
          const std::uint32_t next = sharing.first[0] == current ? sharing.first[1] : sharing.first[0];
          const VertexId d = third_vertex(triangles[next], p, q);
          if (d == c) break;
          const Point2 pd = place_opposite(pp, pq, length3(p, d), length3(q, d), previous);
          if (cross(pa, pd) > 0 && cross(pd, pb) > 0) {
            add_virtual(c, a, d, pc, pa, pd);
            add_virtual(c, d, b, pc, pd, pb);
            break;
          }
          if (cross(pa, pd) <= 0) {  // D lies beyond A's side: C's angle crosses edge DQ
            previous = pp;
            p = d;
            pp = pd;
          } else {  // beyond B's side: the angle crosses edge PD
            previous = pq;
            q = d;
            pq = pd;
          }
          current = next;
        }
      }
    }
  });
  std::vector<std::pair<VertexId, VirtualUpdate>> virtual_records;
  for (const auto& listed : virtual_pieces) virtual_records.insert(virtual_records.end(), listed.begin(), listed.end());

  TriangleStencils result;
  to_compressed_rows(triangle_records, mesh.vertex_count(), result.triangle_offsets, result.triangles);
  to_compressed_rows(virtual_records, mesh.vertex_count(), result.virtual_offsets, result.virtual_updates);
  return result;
}

}  // namespace meshparticles
