#include "pipeline/point_set_measurement.hpp"

#include <algorithm>

#include "common/user_error.hpp"
#include "pipeline/sigma_check.hpp"

namespace meshparticles {

void set_refinement(PointSetsRequest& request, const std::string& refine) {
  request.uniform_levels.reset();
  request.spread_mesh = refine == "spread";
  if (refine == "auto" || refine == "spread") return;
  if (refine.size() != 1 || refine[0] < '0' || refine[0] > '8') {
    throw UserError("refine: expected auto, spread or 0 to 8, got '" + refine + "'");
  }
  request.uniform_levels = unsigned(refine[0] - '0');
}

PointSetsMeasurement measure_point_sets(const SurfaceMesh& input, const PointSetsRequest& request) {
  check_distances_request(request.distances);
  if (request.sigma) check_sigma_computable({request.potential, *request.sigma});
  // Points between the input's vertices are measured as vertices of a
  // refined mesh, inserted where they are.
  PointSetsMeasurement out{measuring_mesh(input, request.points, request.uniform_levels, request.spread_mesh), {}, {}, {}};
  std::vector<SnappedParticles> placed = place_on_vertices(out.measuring.refined, input, request.points);
  const SurfaceMesh& mesh = out.measuring.refined.mesh;
  // A local store's cutoff scales with the spacing of the set with the fewest particles (the widest).
  std::size_t fewest = request.points.front().size();
  for (const auto& set : request.points) fewest = std::min(fewest, set.size());
  const ObtainedDistances obtained = obtain_distances(
      mesh, request.geodesics, plan_distances(mesh, request.distances, std::min(fewest, mesh.vertex_count()), false));
  const GeodesicMethod method = host_march_method(request.geodesics.method);
  for (std::size_t k = 0; k < request.points.size(); ++k) {
    out.sets.push_back(measure_particle_file(mesh, *obtained.store, method, request.names[k], std::move(placed[k]),
                                             request.potential, request.sigma, request.geodesics.quiet));
  }
  if (out.sets.size() == 2) {
    out.mean_a_to_b = mean_distance_to_nearest(mesh, method, out.sets[0].snapped.positions, out.sets[1].snapped.positions);
    out.mean_b_to_a = mean_distance_to_nearest(mesh, method, out.sets[1].snapped.positions, out.sets[0].snapped.positions);
  }
  return out;
}

}  // namespace meshparticles
