#include "particles/surface_neighbours.hpp"

#include <algorithm>
#include <limits>

namespace meshparticles {

SurfaceNeighbours::SurfaceNeighbours(const SurfaceMesh& mesh, const GeodesicSolver& solver)
    : mesh_(mesh), solver_(solver), distance_(mesh.vertex_count(), std::numeric_limits<float>::infinity()) {
  const auto& p = mesh.positions();
  for (const Triangle& t : mesh.triangles()) {
    longest_edge_ = std::max({longest_edge_, distance(p[t[0]], p[t[1]]), distance(p[t[1]], p[t[2]]),
                              distance(p[t[2]], p[t[0]])});
  }
}

void SurfaceNeighbours::look_from(const SurfaceLocation& from, double radius) {
  for (const auto& [v, d] : within_) distance_[v] = std::numeric_limits<float>::infinity();
  const Triangle& t = mesh_.triangles()[from.triangle];
  const auto& p = mesh_.positions();
  const double starts[3] = {distance(from.at, p[t[0]]), distance(from.at, p[t[1]]), distance(from.at, p[t[2]])};
  // Past the radius by an edge: a point within it has every corner of its
  // triangle marched.
  marched_ = radius + longest_edge_;
  solver_.solve_ball_from(t, starts, marched_, scratch_, within_);
  for (const auto& [v, d] : within_) distance_[v] = d;
}

double SurfaceNeighbours::at_least(const SurfaceLocation& to) const {
  const auto& p = mesh_.positions();
  double bound = 0;
  for (const VertexId c : mesh_.triangles()[to.triangle]) {
    const double along = std::min(double(distance_[c]), marched_);  // a corner not marched lies beyond
    bound = std::max(bound, along - distance(p[c], to.at));
  }
  return bound;
}

}  // namespace meshparticles
