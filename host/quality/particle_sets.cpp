#include "quality/particle_sets.hpp"

#include <algorithm>

#include "particles/spread_working_mesh.hpp"

namespace meshparticles {

MeasuringMesh measuring_mesh(const SurfaceMesh& mesh, const std::vector<std::vector<Vec3>>& sets,
                             std::optional<unsigned> uniform_levels, bool spread) {
  if (uniform_levels) return {refine_by_midpoints(mesh, *uniform_levels), false};
  std::size_t fewest = mesh.vertex_count();
  for (const auto& set : sets) fewest = std::min(fewest, set.size());
  fewest = std::max<std::size_t>(fewest, 1);
  const double tolerance = kOnVertex * hexagonal_spacing(mesh.area(), fewest);
  const auto on_vertices = [&](const SurfaceMesh& refined) {
    return std::all_of(sets.begin(), sets.end(), [&](const std::vector<Vec3>& set) {
      return snap_to_vertices(refined, set).largest_snap <= tolerance;
    });
  };
  // Points on the input's vertices (a paper run's, a vertex sampler's) are
  // measured on the input, as the paper run measured them itself.
  if (!spread && on_vertices(mesh)) return {refine_by_midpoints(mesh, 0), false};
  MeasuringMesh working{build_working_mesh(mesh, plan_working_mesh(mesh, fewest, kSpreadVerticesPerParticle)), true};
  if (spread || on_vertices(working.refined.mesh)) return working;
  const double most = std::min(double(kMeasuringMaxVertices),
                               std::max(double(mesh.vertex_count()), kMeasuringVerticesPerParticle * double(fewest)));
  for (unsigned level = 0;; ++level) {  // (round 0, the mesh itself, is known to miss)
    RefinedMesh refined = refine_by_midpoints(mesh, level);
    if ((level > 0 && on_vertices(refined.mesh)) || double(refined_vertex_count(mesh, level + 1)) > most) {
      return {std::move(refined), false};
    }
  }
}

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
