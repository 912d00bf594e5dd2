#include "pipeline/distances.hpp"

#include <chrono>

namespace meshparticles {

ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& request) {
  const auto started = std::chrono::steady_clock::now();
  ObtainedDistances obtained;
  obtained.store = std::make_unique<DistanceTable>(load_or_compute_distances(mesh, request, obtained.source));
  obtained.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return obtained;
}

}  // namespace meshparticles
