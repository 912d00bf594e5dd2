#include "quality/particle_sets.hpp"


namespace meshparticles {

MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceStore& distances, GeodesicMethod method,
                                  const std::string& path, const std::vector<Vec3>& points, Potential potential,
                                  std::optional<double> sigma, bool quiet) {
  MeasuredSet set;
  set.path = path;
  set.snapped = snap_to_vertices(mesh, points);
  const std::size_t n = set.snapped.positions.size();
  set.energy = {potential, sigma.value_or(default_sigma(potential, mesh.area(), n))};
  set.quality = measure_quality(mesh, distances, set.snapped.positions, set.energy,
                                distance_to_nearest_particle(mesh, method, set.snapped.positions), quiet);
  return set;
}

double mean_distance_to_nearest(const SurfaceMesh& mesh, GeodesicMethod method, const std::vector<VertexId>& from,
                                const std::vector<VertexId>& to) {
  const std::vector<float> to_nearest = distance_to_nearest_particle(mesh, method, to);
  double sum = 0;
  for (const VertexId a : from) sum += to_nearest[a];
  return from.empty() ? 0.0 : sum / double(from.size());
}

}  // namespace meshparticles
