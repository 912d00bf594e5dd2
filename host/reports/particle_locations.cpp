#include "reports/particle_locations.hpp"

namespace meshparticles {

std::vector<ParticleLocation> particle_locations(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  const SurfaceMesh& surface = result.particle_mesh(input);
  // A paper run's particles sit on the input's vertices.
  const std::vector<SurfacePoint> at_vertices = result.spread ? std::vector<SurfacePoint>() : vertex_surface_points(input);
  const std::vector<SurfacePoint>& on_input = result.spread ? result.spread->working->on_input : at_vertices;
  std::vector<ParticleLocation> locations(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const SurfacePoint& point = on_input[positions[i]];
    ParticleLocation& location = locations[i];
    location.at = surface.positions()[positions[i]];
    location.input_vertex = input.input_id(result.spread ? point.nearest_corner(input) : positions[i]);
    for (int k = 0; k < 3; ++k) {
      location.on_input.corners[k] = input.input_id(point.corners[k]);
      location.on_input.weights[k] = point.weights[k];
    }
  }
  return locations;
}

}  // namespace meshparticles
