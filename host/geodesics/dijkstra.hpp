#pragma once
// Dijkstra on the edge graph: the baseline. Paths are confined to mesh edges,
// so distances are overestimated (several percent on irregular meshes).
#include "geodesics/single_source.hpp"

namespace meshparticles {

class EdgeDijkstra : public SingleSourceGeodesics {
 public:
  explicit EdgeDijkstra(const SurfaceMesh& mesh);
  void solve(VertexId source, std::span<double> distances, SolverScratch& scratch) const override;

 private:
  const SurfaceMesh& mesh_;
  std::vector<float> edge_lengths_;  // parallel to mesh.ring_neighbors()
};

}  // namespace meshparticles
