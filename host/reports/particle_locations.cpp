#include "reports/particle_locations.hpp"

#include "mesh/midpoint_refinement.hpp"

namespace meshparticles {

namespace {

// The corner of the location's triangle nearest to its point (ties: the first).
VertexId nearest_corner(const SurfaceMesh& mesh, const SurfaceLocation& location) {
  const Triangle& corners = mesh.triangles()[location.triangle];
  const auto& positions = mesh.positions();
  int best = 0;
  for (int k = 1; k < 3; ++k) {
    if (distance(location.at, positions[corners[k]]) < distance(location.at, positions[corners[best]])) best = k;
  }
  return corners[best];
}

}  // namespace

std::vector<SurfaceLocation> particles_on_input(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  // A paper run's particles sit on the input's vertices.
  const std::vector<SurfaceLocation> at_vertices = result.spread ? std::vector<SurfaceLocation>() : vertex_locations(input);
  const std::vector<SurfaceLocation>& on_input = result.spread ? result.spread->working->on_input : at_vertices;
  std::vector<SurfaceLocation> locations;
  locations.reserve(positions.size());
  for (const VertexId v : positions) locations.push_back(on_input[v]);
  return locations;
}

std::vector<ParticleLocation> particle_locations(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  const SurfaceMesh& surface = result.particle_mesh(input);
  const std::vector<SurfaceLocation> on_input = particles_on_input(input, result);
  std::vector<ParticleLocation> locations(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const SurfaceLocation& point = on_input[i];
    const Triangle& corners = input.triangles()[point.triangle];
    ParticleLocation& location = locations[i];
    location.at = surface.positions()[positions[i]];
    location.input_vertex = input.input_id(result.spread ? nearest_corner(input, point) : positions[i]);
    for (int k = 0; k < 3; ++k) {
      location.on_input.corners[k] = input.input_id(corners[k]);
      location.on_input.weights[k] = point.weights[k];
    }
  }
  return locations;
}

}  // namespace meshparticles
