#include "geodesics/dijkstra.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "geodesics/shortest_first_queue.hpp"

namespace meshparticles {

std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh) {
  std::vector<float> lengths(mesh.ring_neighbors().size());
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    for (std::uint32_t k = mesh.ring_offsets()[v]; k < mesh.ring_offsets()[v + 1]; ++k) {
      lengths[k] = float(distance(mesh.positions()[v], mesh.positions()[mesh.ring_neighbors()[k]]));
    }
  }
  return lengths;
}

EdgeDijkstra::EdgeDijkstra(const SurfaceMesh& mesh) : mesh_(mesh), edge_lengths_(ring_edge_lengths(mesh)) {}

void EdgeDijkstra::solve(VertexId source, std::span<double> distances, SolverScratch& scratch) const {
  ShortestFirstQueue queue(source, distances, scratch);
  const auto& offsets = mesh_.ring_offsets();
  const auto& neighbors = mesh_.ring_neighbors();
  while (auto x = queue.pop_next()) {
    const double dx = distances[*x];
    for (std::uint32_t k = offsets[*x]; k < offsets[*x + 1]; ++k) queue.offer(neighbors[k], dx + edge_lengths_[k]);
  }
}

}  // namespace meshparticles
