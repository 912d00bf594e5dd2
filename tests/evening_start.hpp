#pragma once
// The evening step's start as a spread run makes it (pipeline/spread_method):
// a farthest start, swept on the vertices, each particle then a point of a
// triangle. Shared by the evening tests on the host and on a device.
#include <algorithm>
#include <memory>
#include <vector>

#include "geodesics/solver_factory.hpp"
#include "mesh/surface_walk.hpp"
#include "particles/farthest_point_optimization.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_params.hpp"
#include "quality/distribution_quality.hpp"

namespace meshparticles::testing {

struct EveningStart {
  std::unique_ptr<GeodesicSolver> solver;  // fast marching on the mesh
  double d_hex = 0;
  std::vector<VertexId> start;             // the farthest start
  SpreadOutcome swept;                     // its sweeps
  double start_cover = 0;                  // the farthest start's geodesic covering radius
  std::vector<SurfaceLocation> from;       // the swept vertices, as the evening takes them
};

inline EveningStart evening_start(const SurfaceMesh& mesh, std::size_t particles) {
  EveningStart s;
  s.solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  s.d_hex = hexagonal_spacing(mesh.area(), particles);
  PlacementRequest placement;
  placement.init = Init::farthest;
  placement.particle_count = particles;
  s.start = place_particles(mesh, *s.solver, placement, true);
  s.swept = optimize_farthest_points(mesh, *s.solver, s.start, 100, 1e-3 * s.d_hex, 1e-4 * s.d_hex, true);
  for (const float d : distance_to_nearest_particle(*s.solver, mesh, s.start)) {
    s.start_cover = std::max(s.start_cover, double(d));
  }
  const SurfaceWalk walk(mesh);
  for (const VertexId v : s.swept.positions) s.from.push_back(walk.at_vertex(v));
  return s;
}

// Moves for the diagrams' update tests: every third of `points` steps half a
// spacing (at most half the way) toward the next, and point 1 jumps across
// the mesh, beside the point halfway round the list. Which moved.
inline std::vector<char> move_a_third_and_one_far(const SurfaceMesh& mesh, double d_hex,
                                                  std::vector<SurfaceLocation>& points) {
  const SurfaceWalk walk(mesh);
  std::vector<char> moved(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); i += 3) {
    const Vec3 toward = points[(i + 1) % points.size()].at - points[i].at;
    const double step = std::min(0.5 * d_hex, 0.5 * norm(toward));
    points[i] = walk.walk(points[i].triangle, points[i].at + (step / norm(toward)) * toward);
    moved[i] = 1;
  }
  const std::size_t far = points.size() / 2 + 1;
  points[1] = walk.walk(points[far].triangle, points[far].at + 0.4 * (points[far + 1].at - points[far].at));
  moved[1] = 1;
  return moved;
}

}  // namespace meshparticles::testing
