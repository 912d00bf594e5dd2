#include "geodesics/dijkstra.hpp"

#include "geodesics/shortest_first_queue.hpp"

namespace meshparticles {

EdgeDijkstra::EdgeDijkstra(const SurfaceMesh& mesh)
    : GeodesicSolver(mesh.vertex_count()), mesh_(mesh), edge_lengths_(ring_edge_lengths(mesh)) {}

void EdgeDijkstra::march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                         double max_distance, std::span<const float> bound) const {
  ShortestFirstQueue queue(sources, distances, scratch, max_distance, bound);
  const auto& offsets = mesh_.ring_offsets();
  const auto& neighbors = mesh_.ring_neighbors();
  while (auto x = queue.pop_next()) {
    const double dx = distances[*x];
    for (std::uint32_t k = offsets[*x]; k < offsets[*x + 1]; ++k) queue.offer(neighbors[k], dx + edge_lengths_[k]);
  }
}

}  // namespace meshparticles
