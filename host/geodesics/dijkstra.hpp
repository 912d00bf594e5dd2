#pragma once
// Dijkstra on the edge graph: the baseline. Paths are confined to mesh edges,
// so distances are overestimated (several percent on irregular meshes).
#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

class EdgeDijkstra : public GeodesicSolver {
 public:
  explicit EdgeDijkstra(const SurfaceMesh& mesh);

 protected:
  void march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
             double max_distance, std::span<const float> bound,
             std::span<const std::uint32_t> origins = {}) const override;

 private:
  const SurfaceMesh& mesh_;
  std::vector<float> edge_lengths_;  // parallel to mesh.ring_neighbors()
};

}  // namespace meshparticles
