#include "geodesics/dijkstra.hpp"

#include "geodesics/shortest_first_queue.hpp"

namespace meshparticles {

EdgeDijkstra::EdgeDijkstra(const SurfaceMesh& mesh)
    : GeodesicSolver(mesh.vertex_count()), mesh_(mesh), edge_lengths_(ring_edge_lengths(mesh)) {}

void EdgeDijkstra::march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                         double max_distance, std::span<const float> bound,
                         std::span<const std::uint32_t> origins) const {
  ShortestFirstQueue queue(sources, distances, scratch, max_distance, bound, !origins.empty());
  std::vector<std::uint32_t>& origin = scratch.origin;
  for (std::uint32_t k = 0; k < sources.size(); ++k) origin[sources[k]] = origins.empty() ? k : origins[k];
  const auto& offsets = mesh_.ring_offsets();
  const auto& neighbors = mesh_.ring_neighbors();
  while (auto x = queue.pop_next()) {
    const double dx = distances[*x];
    for (std::uint32_t k = offsets[*x]; k < offsets[*x + 1]; ++k) {
      if (!queue.lower(neighbors[k], dx + edge_lengths_[k])) continue;
      origin[neighbors[k]] = origin[*x];
      queue.requeue(neighbors[k]);
    }
  }
}

}  // namespace meshparticles
