#include "quality/particle_sets.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "mesh/point_insertion.hpp"
#include "mesh/surface_walk.hpp"
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
  return {build_working_mesh(mesh, plan_working_mesh(mesh, fewest, kSpreadVerticesPerParticle)), true};
}

std::vector<SnappedParticles> place_on_vertices(RefinedMesh& measuring, const SurfaceMesh& input,
                                                const std::vector<std::vector<Vec3>>& sets) {
  const SurfaceMesh& mesh = measuring.mesh;
  const SurfaceWalk walk(mesh);
  std::vector<SnappedParticles> placed;
  std::vector<TrianglePoint> off_vertices;
  std::vector<std::pair<std::size_t, std::size_t>> which;  // (set, point) of each in off_vertices
  for (std::size_t k = 0; k < sets.size(); ++k) {
    placed.push_back(snap_to_vertices(mesh, sets[k]));
    for (std::size_t i = 0; i < sets[k].size(); ++i) {
      const VertexId nearest = placed[k].positions[i];
      std::uint32_t triangle = 0;
      if (distance(mesh.positions()[nearest], sets[k][i]) <= kOnVertexExactly * mesh.mean_edge_length() ||
          !walk.first_triangle(nearest, triangle)) {
        continue;
      }
      const SurfaceLocation location = walk.walk(triangle, sets[k][i]);
      off_vertices.push_back({location.triangle, location.weights});
      which.emplace_back(k, i);
    }
  }
  if (!off_vertices.empty()) {
    InsertedPoints inserted = insert_points(measuring, input, off_vertices);
    for (std::size_t m = 0; m < which.size(); ++m) placed[which[m].first].positions[which[m].second] = inserted.vertices[m];
    measuring = std::move(inserted.refined);
  }
  for (std::size_t k = 0; k < sets.size(); ++k) {  // how far each point is from where it is measured
    placed[k].largest_snap = 0;
    placed[k].largest_snap_particle = 0;
    for (std::size_t i = 0; i < sets[k].size(); ++i) {
      const double d = distance(measuring.mesh.positions()[placed[k].positions[i]], sets[k][i]);
      if (d > placed[k].largest_snap) std::tie(placed[k].largest_snap, placed[k].largest_snap_particle) = std::pair(d, i);
    }
  }
  return placed;
}

MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceStore& distances, GeodesicMethod method,
                                  const std::string& path, SnappedParticles placed, Potential potential,
                                  std::optional<double> sigma, bool quiet) {
  MeasuredSet set;
  set.path = path;
  set.snapped = std::move(placed);
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
