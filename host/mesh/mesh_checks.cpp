#include "mesh/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

std::string plural(std::size_t count, const std::string& one, const std::string& many = "") {
  return std::to_string(count) + " " + (count == 1 ? one : many.empty() ? one + "s" : many);
}

// Counts against the header, where the format has one; then whether every
// element the reader produced was actually read.
void check_counts(const PolygonSoup& soup, const std::string& label) {
  const std::size_t readable_vertices = soup.first_unreadable_vertex.value_or(soup.vertices.size());
  const std::size_t readable_faces = soup.first_unreadable_face.value_or(soup.faces.size());
  if (soup.declared_vertices && *soup.declared_vertices != readable_vertices) {
    throw UserError(label + ": header declares " + plural(*soup.declared_vertices, "vertex", "vertices") +
                    " but " + std::to_string(readable_vertices) + " could be read (truncated file or malformed number)");
  }
  if (soup.declared_faces && *soup.declared_faces != readable_faces) {
    throw UserError(label + ": header declares " + plural(*soup.declared_faces, "face") + " but " +
                    std::to_string(readable_faces) + " could be read (truncated file or malformed number)");
  }
  if (soup.vertices.empty()) throw UserError(label + ": the mesh has no vertices");
  if (soup.faces.empty()) throw UserError(label + ": the mesh has no faces");
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
  triangles.reserve(soup.faces.size());
  std::size_t polygons = 0;
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    const auto& face = soup.faces[f];
    const std::string where = label + ": face " + std::to_string(f);
    if (face.size() < 3) throw UserError(where + " has only " + plural(face.size(), "vertex", "vertices"));
    for (long long index : face) {
      if (index < 0 || index >= vertex_count) {
        throw UserError(where + " refers to vertex " + std::to_string(index) + ", out of range (the file has " +
                        plural(soup.vertices.size(), "vertex", "vertices") + ")");
      }
    }
    std::vector<long long> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (const auto repeat = std::adjacent_find(sorted.begin(), sorted.end()); repeat != sorted.end()) {
      throw UserError(where + " uses vertex " + std::to_string(*repeat) + " more than once");
    }
    if (face.size() > 3) ++polygons;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.push_back({VertexId(face[0]), VertexId(face[k]), VertexId(face[k + 1])});
    }
  }
  if (polygons > 0) warnings.push_back(label + ": " + plural(polygons, "polygon") + " with more than 3 vertices triangulated");
  return triangles;
}

// Every edge in at most two triangles, no triangle twice, and around every
// vertex one fan of triangles (not two cones touching at a point).
void check_manifold(const std::vector<Triangle>& triangles, std::size_t vertex_count,
                    const std::string& label, std::vector<std::string>& warnings) {
  std::map<std::pair<VertexId, VertexId>, int> edge_faces;
  std::size_t same_direction_edges = 0;
  std::set<std::pair<VertexId, VertexId>> directed;
  std::map<Triangle, std::size_t> first_with_vertices;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    Triangle key = triangles[f];
    std::sort(key.begin(), key.end());
    if (const auto [it, inserted] = first_with_vertices.emplace(key, f); !inserted) {
      throw UserError(label + ": triangle " + std::to_string(f) + " repeats triangle " +
                      std::to_string(it->second) + " (same three vertices)");
    }
    for (int k = 0; k < 3; ++k) {
      const VertexId a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      if (++edge_faces[{std::min(a, b), std::max(a, b)}] == 3) {
        throw UserError(label + ": non-manifold edge " + std::to_string(a) + "-" + std::to_string(b) +
                        " is shared by more than two faces");
      }
      if (!directed.insert({a, b}).second) ++same_direction_edges;
    }
  }
  if (same_direction_edges > 0) {
    warnings.push_back(label + ": " + plural(same_direction_edges, "edge") +
                       " where neighbouring faces disagree in orientation (harmless here: only distances matter)");
  }

  // The link of v: edges opposite v in its triangles. Manifold iff connected.
  std::vector<std::vector<std::pair<VertexId, VertexId>>> link(vertex_count);
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (link[v].empty()) continue;
    std::map<VertexId, VertexId> parent;
    const auto root = [&parent](VertexId x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const auto& [a, b] : link[v]) {
      parent.emplace(a, a);
      parent.emplace(b, b);
    }
    std::size_t fans = parent.size();
    for (const auto& [a, b] : link[v]) {
      const VertexId ra = root(a), rb = root(b);
      if (ra != rb) {
        parent[ra] = rb;
        --fans;
      }
    }
    if (fans > 1) {
      throw UserError(label + ": non-manifold vertex " + std::to_string(v) + " (its triangles form " +
                      std::to_string(fans) + " separate fans)");
    }
  }
}

}  // namespace

SurfaceMesh build_checked_mesh(const PolygonSoup& soup, const std::string& label,
                               std::vector<std::string>& warnings) {
  check_counts(soup, label);
  check_coordinates(soup, label);
  std::vector<Triangle> triangles = triangulate_checked_faces(soup, label, warnings);
  check_manifold(triangles, soup.vertices.size(), label, warnings);

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
  // they make geodesic updates ill-conditioned. "Zero" is relative to the
  // triangle's own edge lengths, so the test does not depend on the mesh scale.
  std::size_t degenerate = 0;
  for (const Triangle& t : triangles) {
    const Vec3 &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
    const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
    if (triangle_area(a, b, c) <= 1e-12 * longest * longest) ++degenerate;
  }
  if (degenerate > 0) warnings.push_back(label + ": " + plural(degenerate, "degenerate (zero-area) triangle"));

  return SurfaceMesh(std::move(positions), std::move(triangles), std::move(input_ids), soup.vertices.size());
}

}  // namespace meshparticles
