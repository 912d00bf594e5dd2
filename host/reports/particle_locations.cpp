#include "reports/particle_locations.hpp"

namespace meshparticles {

namespace {

// A paper run's particle sits on a vertex: the first triangle holding it,
// with all the weight on that corner (an isolated vertex: itself, thrice).
std::vector<SurfacePoint> points_at_vertices(const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  constexpr VertexId kNone = 0xFFFFFFFFu;
  std::vector<VertexId> first_triangle(mesh.vertex_count(), kNone);
  for (const VertexId v : positions) first_triangle[v] = kNone - 1;  // wanted, not found yet
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
    for (const VertexId v : mesh.triangles()[t]) {
      if (first_triangle[v] == kNone - 1) first_triangle[v] = t;
    }
  }
  std::vector<SurfacePoint> points;
  points.reserve(positions.size());
  for (const VertexId v : positions) {
    if (first_triangle[v] >= kNone - 1) {
      points.push_back({{v, v, v}, {1, 0, 0}});
      continue;
    }
    const Triangle& corners = mesh.triangles()[first_triangle[v]];
    SurfacePoint point{corners, {0, 0, 0}};
    for (int k = 0; k < 3; ++k) point.weights[k] = corners[k] == v ? 1.0 : 0.0;
    points.push_back(point);
  }
  return points;
}

}  // namespace

std::vector<ParticleLocation> particle_locations(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  const SurfaceMesh& surface = result.particle_mesh(input);
  std::vector<SurfacePoint> points;
  if (result.working) {
    for (const VertexId v : positions) points.push_back(result.working->on_input[v]);
  } else {
    points = points_at_vertices(input, positions);
  }
  std::vector<ParticleLocation> locations(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    ParticleLocation& location = locations[i];
    location.at = surface.positions()[positions[i]];
    location.input_vertex = input.input_id(result.working ? points[i].nearest_corner(input) : positions[i]);
    for (int k = 0; k < 3; ++k) {
      location.corners[k] = input.input_id(points[i].corners[k]);
      location.weights[k] = points[i].weights[k];
    }
  }
  return locations;
}

}  // namespace meshparticles
