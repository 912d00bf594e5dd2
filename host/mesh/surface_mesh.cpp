#include "mesh/surface_mesh.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace meshparticles {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * norm(cross(b - a, c - a));
}

double longest_edge(const SurfaceMesh& mesh) {
  const auto& x = mesh.positions();
  double longest = 0;
  for (const Triangle& t : mesh.triangles()) {
    for (int k = 0; k < 3; ++k) longest = std::max(longest, distance(x[t[k]], x[t[(k + 1) % 3]]));
  }
  return longest;
}

namespace {

// Union-find with path halving: enough for labelling components once.
std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

SurfaceMesh::SurfaceMesh(std::vector<Vec3> positions, std::vector<Triangle> triangles,
                         std::vector<VertexId> input_ids, std::size_t input_vertex_count)
    : positions_(std::move(positions)),
      triangles_(std::move(triangles)),
      input_ids_(std::move(input_ids)),
      input_vertex_count_(input_vertex_count ? input_vertex_count : positions_.size()) {
  const std::size_t n = positions_.size();
  std::vector<std::uint8_t> in_triangle(n, 0);
  for (const Triangle& t : triangles_) in_triangle[t[0]] = in_triangle[t[1]] = in_triangle[t[2]] = 1;
  if (const auto lone = std::find(in_triangle.begin(), in_triangle.end(), 0); lone != in_triangle.end()) {
    throw std::invalid_argument("SurfaceMesh: vertex " + std::to_string(lone - in_triangle.begin()) +
                                " is in no triangle");
  }

  // Each undirected edge (a <= b) once per triangle using it, listed under
  // a by a counting sort, each a's few b sorted: a run of one means
  // boundary. The edges come in the order of a map on (a, b), without its
  // node per edge (on a million vertices the map was most of the mesh's
  // construction) or a sort of all the uses (3 per triangle).
  std::vector<std::uint32_t> use_offsets(n + 1, 0);
  for (const Triangle& t : triangles_) {
    for (int k = 0; k < 3; ++k) ++use_offsets[std::min(t[k], t[(k + 1) % 3]) + 1];
    area_ += triangle_area(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
  }
  for (std::size_t v = 0; v < n; ++v) use_offsets[v + 1] += use_offsets[v];
  std::vector<VertexId> larger_ends(use_offsets[n]);
  {
    std::vector<std::uint32_t> next(use_offsets.begin(), use_offsets.end() - 1);
    for (const Triangle& t : triangles_) {
      for (int k = 0; k < 3; ++k) {
        const VertexId a = t[k], b = t[(k + 1) % 3];
        larger_ends[next[std::min(a, b)]++] = std::max(a, b);
      }
    }
  }
  struct Edge {
    VertexId first, second;
    bool boundary;
  };
  std::vector<Edge> edges;
  for (std::size_t a = 0; a < n; ++a) {
    const auto first = larger_ends.begin() + use_offsets[a], last = larger_ends.begin() + use_offsets[a + 1];
    std::sort(first, last);
    for (auto begin = first, end = first; begin != last; begin = end) {
      while (end != last && *end == *begin) ++end;
      edges.push_back({VertexId(a), *begin, end - begin == 1});
    }
  }
  std::vector<VertexId>().swap(larger_ends);

  // Each ring is sorted as it is filled: edges come in order of (first, second).
  ring_offsets_.assign(n + 1, 0);
  for (const Edge& e : edges) {
    ++ring_offsets_[e.first + 1];
    ++ring_offsets_[e.second + 1];
  }
  for (std::size_t v = 0; v < n; ++v) ring_offsets_[v + 1] += ring_offsets_[v];
  ring_neighbors_.resize(ring_offsets_[n]);
  std::vector<std::uint32_t> fill(ring_offsets_.begin(), ring_offsets_.end() - 1);
  boundary_.assign(n, 0);
  double edge_length_sum = 0;
  for (const Edge& e : edges) {
    ring_neighbors_[fill[e.first]++] = e.second;
    ring_neighbors_[fill[e.second]++] = e.first;
    if (e.boundary) boundary_[e.first] = boundary_[e.second] = 1;
    edge_length_sum += distance(positions_[e.first], positions_[e.second]);
  }
  mean_edge_length_ = edges.empty() ? 0.0 : edge_length_sum / double(edges.size());

  // Components numbered in order of their smallest vertex id.
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Edge& e : edges) parent[find_root(parent, e.first)] = find_root(parent, e.second);
  component_.assign(n, 0);
  std::map<std::uint32_t, std::uint32_t> label_of_root;
  for (std::size_t v = 0; v < n; ++v) {
    const auto root = find_root(parent, std::uint32_t(v));
    const auto [it, inserted] = label_of_root.emplace(root, std::uint32_t(label_of_root.size()));
    component_[v] = it->second;
  }
  component_count_ = label_of_root.size();
}

std::size_t SurfaceMesh::max_valence() const {
  std::size_t best = 0;
  for (std::size_t v = 0; v < vertex_count(); ++v) best = std::max(best, valence(VertexId(v)));
  return best;
}

std::optional<VertexId> SurfaceMesh::vertex_of_input_id(std::size_t input_id) const {
  if (input_ids_.empty()) {
    if (input_id < vertex_count()) return VertexId(input_id);
    return std::nullopt;
  }
  const auto it = std::lower_bound(input_ids_.begin(), input_ids_.end(), input_id);  // ids kept in file order
  if (it == input_ids_.end() || *it != input_id) return std::nullopt;
  return VertexId(it - input_ids_.begin());
}

std::size_t SurfaceMesh::boundary_vertex_count() const {
  return std::size_t(std::count(boundary_.begin(), boundary_.end(), 1));
}

}  // namespace meshparticles
