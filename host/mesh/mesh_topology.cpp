#include "mesh/mesh_topology.hpp"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

// Disjoint sets of vertex ids, to count the boundary's loops.
class VertexSets {
 public:
  explicit VertexSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), VertexId(0)); }
  VertexId root(VertexId v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(VertexId a, VertexId b) { parent_[root(a)] = root(b); }

 private:
  std::vector<VertexId> parent_;
};

}  // namespace

MeshTopology mesh_topology(const SurfaceMesh& mesh) {
  std::vector<std::pair<VertexId, VertexId>> edges;
  edges.reserve(3 * mesh.triangle_count());
  for (const Triangle& t : mesh.triangles()) {
    for (std::size_t k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  VertexSets loops(mesh.vertex_count());
  std::vector<bool> on_boundary(mesh.vertex_count(), false);
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++distinct;
    if (j - i == 1) {  // in one triangle: a boundary edge
      loops.join(edges[i].first, edges[i].second);
      on_boundary[edges[i].first] = on_boundary[edges[i].second] = true;
    }
    i = j;
  }
  MeshTopology topology;
  topology.components = mesh.component_count();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) topology.boundary_loops += on_boundary[v] && loops.root(v) == v;
  topology.euler_characteristic =
      (long long)mesh.vertex_count() - (long long)distinct + (long long)mesh.triangle_count();
  const long long twice_genus =
      2 * (long long)topology.components - topology.euler_characteristic - (long long)topology.boundary_loops;
  if (twice_genus >= 0 && twice_genus % 2 == 0) topology.genus = twice_genus / 2;
  return topology;
}

std::string describe(const MeshTopology& topology) {
  std::string text = plural(topology.components, "component") + ", ";
  text += topology.genus ? "genus " + std::to_string(*topology.genus) : "genus unknown (not a manifold)";
  text += topology.boundary_loops == 0 ? ", no boundary" : ", " + plural(topology.boundary_loops, "boundary loop");
  return text;
}

}  // namespace meshparticles
