#include "mesh/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "common/user_error.hpp"
#include "mesh/coincident_sheets.hpp"
#include "mesh/plural.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

namespace {

void check_not_empty(const PolygonSoup& soup, const std::string& label) {
  if (soup.vertices.empty()) throw UserError(label + ": the mesh has no vertices");
  if (soup.face_count() == 0) throw UserError(label + ": the mesh has no faces");
}

void check_coordinates(const PolygonSoup& soup, const std::string& label) {
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    const Vec3& p = soup.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw UserError(label + ": vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
    }
  }
}

// Checks each face's indices and fans polygons into triangles.
std::vector<Triangle> triangulate_checked_faces(const PolygonSoup& soup, const std::string& label,
                                                std::vector<std::string>& warnings) {
  const auto vertex_count = (long long)soup.vertices.size();
  std::vector<Triangle> triangles;
  triangles.reserve(soup.face_count());
  std::size_t polygons = 0;
  std::vector<long long> sorted;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    const auto face = soup.face(f);
    const std::string where = label + ": face " + std::to_string(f);
    if (face.size() < 3) throw UserError(where + " has only " + plural(face.size(), "vertex", "vertices"));
    for (long long index : face) {
      if (index < 0 || index >= vertex_count) {
        throw UserError(where + " refers to vertex " + std::to_string(index) + ", out of range (the file has " +
                        plural(soup.vertices.size(), "vertex", "vertices") + ")");
      }
    }
    sorted.assign(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    if (const auto repeat = std::adjacent_find(sorted.begin(), sorted.end()); repeat != sorted.end()) {
      throw UserError(where + " uses vertex " + std::to_string(*repeat) + " more than once");
    }
    if (face.size() > 3) ++polygons;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.push_back({VertexId(face[0]), VertexId(face[k]), VertexId(face[k + 1])});
    }
  }
  if (polygons > 0)
    warnings.push_back(label + ": " + plural(polygons, "polygon") + " with more than 3 vertices triangulated");
  return triangles;
}

std::uint64_t ordered_edge_key(VertexId a, VertexId b) { return (std::uint64_t(a) << 32) | b; }

// A triangle with the same three vertices as an earlier one adds nothing to
// a surface and would count its edges twice: dropped, or refused if strict.
void drop_repeated_triangles(std::vector<Triangle>& triangles, const std::string& label,
                             std::vector<std::string>& warnings, bool strict) {
  struct SortedHash {
    std::size_t operator()(const Triangle& t) const {
      return std::hash<std::uint64_t>()(ordered_edge_key(t[0], t[1]) * 0x9E3779B97F4A7C15ull ^ t[2]);
    }
  };
  std::unordered_map<Triangle, std::size_t, SortedHash> first_with_vertices;
  first_with_vertices.reserve(triangles.size());
  std::vector<Triangle> kept;
  kept.reserve(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    Triangle key = triangles[f];
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = first_with_vertices.emplace(key, f);
    if (inserted) {
      kept.push_back(triangles[f]);
    } else if (strict) {
      throw UserError(label + ": triangle " + std::to_string(f) + " repeats triangle " + std::to_string(it->second) +
                      " (same three vertices)");
    }
  }
  if (const std::size_t dropped = triangles.size() - kept.size(); dropped > 0) {
    warnings.push_back(label + ": " + plural(dropped, "repeated triangle") +
                       " (same three vertices as an earlier one) dropped");
    triangles = std::move(kept);
  }
}

// Edges in more than two triangles are kept (each joins all its triangles;
// distances cross from any to any), or refused if strict.
void check_edges(const std::vector<Triangle>& triangles, const std::string& label, std::vector<std::string>& warnings,
                 bool strict) {
  std::vector<std::uint64_t> undirected, directed;
  undirected.reserve(3 * triangles.size());
  directed.reserve(3 * triangles.size());
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const VertexId a = t[k], b = t[(k + 1) % 3];
      undirected.push_back(ordered_edge_key(std::min(a, b), std::max(a, b)));
      directed.push_back(ordered_edge_key(a, b));
    }
  }
  std::sort(undirected.begin(), undirected.end());
  std::size_t nonmanifold = 0;
  std::string example;
  for (std::size_t begin = 0, end = 0; begin < undirected.size(); begin = end) {
    while (end < undirected.size() && undirected[end] == undirected[begin]) ++end;
    if (end - begin <= 2) continue;
    const std::string edge =
        std::to_string(undirected[begin] >> 32) + "-" + std::to_string(undirected[begin] & 0xffffffffu);
    if (strict) throw UserError(label + ": non-manifold edge " + edge + " is shared by more than two faces");
    if (++nonmanifold == 1) example = edge + ", in " + std::to_string(end - begin) + " triangles";
  }
  if (nonmanifold > 0) {
    warnings.push_back(label + ": " + plural(nonmanifold, "non-manifold edge") + " (e.g. " + example +
                       ") kept: each joins all its triangles");
  }
  std::sort(directed.begin(), directed.end());
  std::size_t same_direction_edges = 0;
  for (std::size_t k = 1; k < directed.size(); ++k) same_direction_edges += directed[k] == directed[k - 1];
  if (same_direction_edges > 0) {
    warnings.push_back(label + ": " + plural(same_direction_edges, "edge") +
                       " where neighbouring faces disagree in orientation (harmless here: only distances matter)");
  }
}

// Around a manifold vertex its triangles form one fan: the link (the edges
// opposite it) is connected. Where separate fans meet at a vertex (two
// cones touching at their apexes) it is kept, so a shortest path may pass
// through it, or refused if strict.
void check_vertex_fans(const std::vector<Triangle>& triangles, std::size_t vertex_count, const std::string& label,
                       std::vector<std::string>& warnings, bool strict) {
  const VertexTriangles fans = vertex_triangles(triangles, vertex_count);
  std::size_t pinched = 0;
  std::string example;
  std::vector<VertexId> neighbours;
  std::vector<std::uint32_t> parent;
  for (VertexId v = 0; v < vertex_count; ++v) {
    neighbours.clear();
    for (const std::uint32_t f : fans.around(v)) {
      for (VertexId w : triangles[f]) {
        if (w != v) neighbours.push_back(w);
      }
    }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    if (neighbours.empty()) continue;
    const auto local = [&](VertexId w) {
      return std::uint32_t(std::lower_bound(neighbours.begin(), neighbours.end(), w) - neighbours.begin());
    };
    const auto root = [&](std::uint32_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    parent.resize(neighbours.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::size_t separate = neighbours.size();
    for (const std::uint32_t f : fans.around(v)) {
      const Triangle& t = triangles[f];
      const int corner = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const std::uint32_t a = root(local(t[(corner + 1) % 3])), b = root(local(t[(corner + 2) % 3]));
      if (a != b) {
        parent[a] = b;
        --separate;
      }
    }
    if (separate <= 1) continue;
    if (strict) {
      throw UserError(label + ": non-manifold vertex " + std::to_string(v) + " (its triangles form " +
                      std::to_string(separate) + " separate fans)");
    }
    if (++pinched == 1)
      example = "vertex " + std::to_string(v) + ", where " + std::to_string(separate) + " fans of triangles meet";
  }
  if (pinched > 0) {
    warnings.push_back(label + ": " + plural(pinched, "non-manifold vertex", "non-manifold vertices") + " (e.g. " +
                       example + ") kept: a shortest path may pass through them");
  }
}

// With no area there is no surface to spread particles on: sigma, the
// spacing and every density come from the area and would be 0 (issue 29).
// Refused when the sum is not a finite number (coordinates so large that a
// triangle's area overflows a double), then when every triangle is degenerate
// (its corners at one point or on one line, by the scale-free test in
// build_checked_mesh, so a small mesh, in micrometres say, is never refused
// for its size).
void check_area(double area, bool all_degenerate, const std::string& label) {
  if (!std::isfinite(area)) {
    throw UserError(label + ": the mesh's area is not a finite number (coordinates too large to compute with)");
  }
  if (all_degenerate || !(area > 0)) {
    throw UserError(label +
                    ": the mesh has no area: every triangle is degenerate (its corners at one point or on one line)");
  }
}

}  // namespace

SurfaceMesh build_checked_mesh(const PolygonSoup& soup, const std::string& label, std::vector<std::string>& warnings,
                               const MeshReadOptions& options) {
  warnings.insert(warnings.end(), soup.warnings.begin(), soup.warnings.end());
  check_not_empty(soup, label);
  check_coordinates(soup, label);
  std::vector<Triangle> triangles = triangulate_checked_faces(soup, label, warnings);
  drop_repeated_triangles(triangles, label, warnings, options.strict);
  check_edges(triangles, label, warnings, options.strict);
  check_vertex_fans(triangles, soup.vertices.size(), label, warnings, options.strict);

  // Drop vertices no triangle uses; keep their input ids for every output.
  std::vector<char> used(soup.vertices.size(), 0);
  for (const Triangle& t : triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<VertexId> new_id(soup.vertices.size(), 0);
  std::vector<Vec3> positions;
  std::vector<VertexId> input_ids;
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    if (!used[v]) continue;
    new_id[v] = VertexId(positions.size());
    positions.push_back(soup.vertices[v]);
    input_ids.push_back(VertexId(v));
  }
  const std::size_t unreferenced = soup.vertices.size() - positions.size();
  if (unreferenced > 0) {
    warnings.push_back(label + ": " + plural(unreferenced, "unreferenced vertex", "unreferenced vertices") +
                       " dropped (outputs keep the file's vertex ids)");
    for (Triangle& t : triangles) {
      for (VertexId& v : t) v = new_id[v];
    }
  } else {
    input_ids.clear();  // identity
  }

  // Zero-area triangles are kept (topology is sound) but worth knowing about:
  // they make geodesic updates ill-conditioned; a mesh of nothing else is
  // refused (check_area). "Zero" is relative to the triangle's own edge
  // lengths, so the test does not depend on the mesh scale (a mesh in
  // micrometres is as good as one in metres).
  std::size_t degenerate = 0;
  double area = 0;  // summed in the order SurfaceMesh sums it
  for (const Triangle& t : triangles) {
    const Vec3 &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
    const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
    const double triangle = triangle_area(a, b, c);
    area += triangle;
    if (triangle <= 1e-12 * longest * longest) ++degenerate;
  }
  check_area(area, degenerate == triangles.size(), label);
  if (degenerate > 0) warnings.push_back(label + ": " + plural(degenerate, "degenerate (zero-area) triangle"));

  SurfaceMesh mesh(std::move(positions), std::move(triangles), std::move(input_ids), soup.vertices.size());
  if (const std::string sheets = coincident_sheets_text(coincident_sheets(mesh)); !sheets.empty()) {
    warnings.push_back(label + ": " + sheets);
  }
  return mesh;
}

}  // namespace meshparticles
