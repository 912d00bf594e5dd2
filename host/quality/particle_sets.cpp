#include "quality/particle_sets.hpp"

#include <algorithm>
#include <limits>

namespace meshparticles {

MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceStore& distances, const std::string& path,
                                  const std::vector<Vec3>& points, Potential potential, std::optional<double> sigma) {
  MeasuredSet set;
  set.path = path;
  set.snapped = snap_to_vertices(mesh, points);
  const std::size_t n = set.snapped.positions.size();
  set.energy = {potential, sigma.value_or(default_sigma(potential, mesh.area(), n))};
  set.quality = measure_quality(mesh, distances, set.snapped.positions, set.energy);
  return set;
}

double mean_distance_to_nearest(const DistanceStore& distances, const std::vector<VertexId>& from,
                                const std::vector<VertexId>& to) {
  double sum = 0;
  std::vector<float> to_others(to.size());
  for (const VertexId a : from) {
    distances.distances_from(a, to, to_others);
    sum += to_others.empty() ? std::numeric_limits<float>::infinity()
                             : *std::min_element(to_others.begin(), to_others.end());
  }
  return from.empty() ? 0.0 : sum / double(from.size());
}

}  // namespace meshparticles
