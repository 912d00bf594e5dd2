#include "quality/particle_sets.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "mesh/nearest_surface_point.hpp"
#include "mesh/point_insertion.hpp"
#include "particles/spread_working_mesh.hpp"

namespace meshparticles {

namespace {

// The share of a set's points on the working mesh's vertices above which
// its finer mesh is tried.
constexpr double kFinerMeshHint = 0.1;

// The share of `points` within `tolerance` of the vertices of `mesh` they
// were snapped to.
double share_on_vertices(const SurfaceMesh& mesh, const std::vector<Vec3>& points, const SnappedParticles& snapped,
                         double tolerance) {
  if (points.empty()) return 1;
  std::size_t on = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    on += distance(mesh.positions()[snapped.positions[i]], points[i]) <= tolerance ? 1 : 0;
  }
  return double(on) / double(points.size());
}

}  // namespace

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
  const WorkingMeshPlan plan = plan_working_mesh(mesh, fewest, kSpreadVerticesPerParticle, kSpreadLongestEdge);
  RefinedMesh working = build_working_mesh(mesh, plan);
  // A spread run whose sweeps went on on a finer mesh (its relaxation not
  // kept) left its particles on that mesh's vertices: measured there, as
  // the run measured them. Built only where some of every set's points sit
  // on the working mesh's vertices, as about a quarter of that finer mesh's
  // vertices do (points between vertices, a relaxed run's or a surface
  // sampler's, almost never do).
  const std::optional<WorkingMeshPlan> finer_plan = plan_finer_working_mesh(mesh, plan);
  if (!finer_plan) return {std::move(working), true};
  bool all_on = true, finer_hinted = true;
  for (const auto& set : sets) {
    const SnappedParticles snapped = snap_to_vertices(working.mesh, set);
    all_on = all_on && snapped.largest_snap <= tolerance;
    finer_hinted = finer_hinted && share_on_vertices(working.mesh, set, snapped, tolerance) >= kFinerMeshHint;
  }
  if (!all_on && finer_hinted) {
    RefinedMesh finer = build_working_mesh(mesh, *finer_plan);
    if (on_vertices(finer.mesh)) return {std::move(finer), true};
  }
  return {std::move(working), true};
}

std::vector<SnappedParticles> place_on_vertices(RefinedMesh& measuring, const SurfaceMesh& input,
                                                const std::vector<std::vector<Vec3>>& sets) {
  const SurfaceMesh& mesh = measuring.mesh;
  const NearestSurfacePoint nearest_point(mesh);
  std::vector<SnappedParticles> placed;
  std::vector<SurfaceLocation> off_vertices;
  std::vector<std::pair<std::size_t, std::size_t>> which;  // (set, point) of each in off_vertices
  for (std::size_t k = 0; k < sets.size(); ++k) {
    placed.push_back(snap_to_vertices(mesh, sets[k]));
    for (std::size_t i = 0; i < sets[k].size(); ++i) {
      const VertexId nearest = placed[k].positions[i];
      if (distance(mesh.positions()[nearest], sets[k][i]) <= kOnVertexExactly * mesh.mean_edge_length()) continue;
      const std::optional<SurfaceLocation> location = nearest_point.find(sets[k][i]);
      if (!location) continue;
      off_vertices.push_back(*location);
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
