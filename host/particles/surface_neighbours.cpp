#include "particles/surface_neighbours.hpp"

#include <algorithm>
#include <limits>

#include <Eigen/Core>

#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

SurfaceNeighbours::SurfaceNeighbours(const SurfaceMesh& mesh, const GeodesicSolver& solver)
    : mesh_(mesh), solver_(solver), longest_edge_(longest_edge(mesh)) {}

void SurfaceNeighbours::look_from(const SurfaceLocation& from, double radius, LookScratch& scratch) const {
  std::vector<float>& distance_of = scratch.distance;
  // The last look's may have been along another surface, of fewer vertices.
  if (distance_of.size() < mesh_.vertex_count()) {
    distance_of.resize(mesh_.vertex_count(), std::numeric_limits<float>::infinity());
  }
  for (const auto& [v, d] : scratch.within) distance_of[v] = std::numeric_limits<float>::infinity();
  const Triangle& t = mesh_.triangles()[from.triangle];
  const auto& p = mesh_.positions();
  const double starts[3] = {distance(from.at, p[t[0]]), distance(from.at, p[t[1]]), distance(from.at, p[t[2]])};
  // Past the radius by an edge: a point within it has every corner of its
  // triangle marched.
  scratch.marched = radius + longest_edge_;
  solver_.solve_ball_from(t, starts, scratch.marched, scratch.solver, scratch.within);
  for (const auto& [v, d] : scratch.within) distance_of[v] = d;
}

double SurfaceNeighbours::at_least(const SurfaceLocation& to, const LookScratch& scratch) const {
  const auto& p = mesh_.positions();
  double bound = 0;
  for (const VertexId c : mesh_.triangles()[to.triangle]) {
    const double along = std::min(double(scratch.distance[c]), scratch.marched);  // a corner not marched lies beyond
    bound = std::max(bound, along - distance(p[c], to.at));
  }
  return bound;
}

void SurfacePairs::begin_step(const std::vector<SurfaceLocation>& at, LookScratch& scratch) {
  if (looked_step_.size() != at.size()) {
    looked_step_.assign(at.size(), 0);
    looked_from_.assign(at.size(), Vec3{});
    seen_.assign(at.size(), {});
  }
  at_ = &at;
  scratch_ = &scratch;
  ++step_;
  looking_ = kNone;
}

bool SurfacePairs::may_be_within(std::uint32_t i, std::uint32_t j, double radius) {
  const std::vector<SurfaceLocation>& at = *at_;
  if (looking_ != i) {
    if (looked_step_[i] > 0 && step_ - looked_step_[i] < kFreshSteps) {
      for (const Seen& seen : seen_[i]) {
        if (seen.particle != j) continue;
        if (seen.bound < radius) return true;
        const double moved = distance(at[i].at, looked_from_[i]) + distance(at[j].at, seen.at);
        if (seen.bound - moved >= radius) return false;
        break;  // no longer surely apart: look again
      }
    }
    look_.look_from(at[i], radius, *scratch_);
    looking_ = i;
    looked_step_[i] = step_;
    looked_from_[i] = at[i].at;
    seen_[i].clear();
  }
  const double bound = look_.at_least(at[j], *scratch_);
  seen_[i].push_back({j, at[j].at, bound});
  return bound < radius;
}

ClosestPair closest_surface_pair(const std::vector<SurfaceLocation>& at, const SurfaceNeighbours& surface, double reach,
                                 LookScratch& scratch) {
  Eigen::Matrix<double, Eigen::Dynamic, 3> points(Eigen::Index(at.size()), 3);
  for (std::size_t i = 0; i < at.size(); ++i) points.row(Eigen::Index(i)) << at[i].at.x, at[i].at.y, at[i].at.z;
  const MatrixRowTree<Eigen::Matrix<double, Eigen::Dynamic, 3>> tree(points);
  ClosestPair closest{reach, 0, 0};
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    bool looked = false;
    for (const Eigen::Index j : tree.within(points.row(i), closest.spacing)) {
      if (j == i) continue;
      if (!looked) surface.look_from(at[std::size_t(i)], reach, scratch);
      looked = true;
      const double straight = (points.row(i) - points.row(j)).norm();
      const double spacing = std::max(straight, surface.at_least(at[std::size_t(j)], scratch));
      if (spacing < closest.spacing) {
        closest = {spacing, std::uint32_t(std::min(i, j)), std::uint32_t(std::max(i, j))};
      }
    }
  }
  return closest;
}

}  // namespace meshparticles
