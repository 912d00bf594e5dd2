#include "mesh/surface_mesh.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace meshparticles {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * norm(cross(b - a, c - a));
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

  // Each undirected edge with the number of triangles using it: one means boundary.
  std::map<std::pair<VertexId, VertexId>, int> edge_faces;
  for (const Triangle& t : triangles_) {
    for (int k = 0; k < 3; ++k) {
      const VertexId a = t[k], b = t[(k + 1) % 3];
      ++edge_faces[{std::min(a, b), std::max(a, b)}];
    }
    area_ += triangle_area(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
  }

  std::vector<std::vector<VertexId>> rings(n);
  boundary_.assign(n, 0);
  double edge_length_sum = 0;
  for (const auto& [edge, faces] : edge_faces) {
    rings[edge.first].push_back(edge.second);
    rings[edge.second].push_back(edge.first);
    if (faces == 1) boundary_[edge.first] = boundary_[edge.second] = 1;
    edge_length_sum += distance(positions_[edge.first], positions_[edge.second]);
  }
  mean_edge_length_ = edge_faces.empty() ? 0.0 : edge_length_sum / double(edge_faces.size());

  ring_offsets_.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    std::sort(rings[v].begin(), rings[v].end());
    ring_offsets_[v + 1] = ring_offsets_[v] + std::uint32_t(rings[v].size());
  }
  ring_neighbors_.reserve(ring_offsets_[n]);
  for (const auto& ring : rings) ring_neighbors_.insert(ring_neighbors_.end(), ring.begin(), ring.end());

  // Components numbered in order of their smallest vertex id.
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& [edge, faces] : edge_faces) {
    parent[find_root(parent, edge.first)] = find_root(parent, edge.second);
  }
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
