#pragma once
// Where particles leave a hole in a surface, and the pull that closes it.
// A packing's pushes only part pairs that are too close: nothing moves a
// particle into an empty place beside it, and a small steady pull (the
// correspondence step) can hold one open. Each point of the surface farther
// than a reach from its particle draws that particle toward it: the
// particles whose Voronoi cells reach into a hole move into it (a step of
// Lloyd's toward the far part of their cells).
//
// A point's particle is the nearest in a straight line, unless the surface
// says that one lies through the air: then the nearest of those whose
// geodesic regions hold its triangle's corners (particles/surface_voronoi).
// A fingertip's hole is drawn shut by the particle on its own finger, not by
// one on the next finger that no step along the surface brings there.
#include <cstdint>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vec3.hpp"
#include "particles/surface_voronoi.hpp"

namespace meshparticles {

class HolePull {
 public:
  // A straight nearest particle is taken to lie through the air where the
  // surface puts the point farther than this many times as far from every
  // particle (a lower bound from its triangle's corners): smooth surfaces
  // stay well under it at a spacing, two fingers side by side far over.
  static constexpr double kThroughTheAir = 1.25;

  // The points of `mesh`'s surface (which must outlive this, as `solver`,
  // built for it), none farther than about `step` from the next: each
  // triangle cut into equal parts with edges under `step`, the parts'
  // centroids, each standing for its part's area.
  HolePull(const SurfaceMesh& mesh, const GeodesicSolver& solver, double step);

  // Per particle of `particles`: over the points farther than `reach` from
  // their particle, that particle's sum of (point - particle) times
  // (1 - reach / distance) times the point's area, over `cell_area` (the
  // descent of the squared overshoots, in a cell's terms). Called again
  // with the same particles moved, it looks again only at the points that
  // the particles' moves may have taken beyond `reach` (a point's distance
  // at the last full look plus how far its particle has moved since), with
  // the surface's regions of the last full look: a fresh look's pulls at a
  // fraction of the cost, but for a point that the rule would now give a
  // particle of its regions where it gave the straight nearest (a full look
  // comes once an eighth of the points had to be looked at). A full look
  // marches in `scratch` (a thread's, lent to every shape's pull in turn).
  std::vector<Vec3> pull(const std::vector<SurfaceLocation>& particles, double reach, double cell_area,
                         SolverScratch& scratch);

  // The largest distance from a point to its particle.
  double cover(const std::vector<SurfaceLocation>& particles) const;

  std::size_t size() const { return size_; }

 private:
  // Calls visit(index, triangle, point, area) for every point, in index order.
  template <typename Visit>
  void for_each_point(Visit&& visit) const;

  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  std::vector<std::uint8_t> parts_;  // per triangle, its parts along an edge
  std::size_t size_ = 0;
  // At the last full look: the particles, their surface regions, each
  // point's particle and its distance (rounded up). A shape's points are
  // held through a whole refinement, so a particle takes two bytes where
  // there are at most 65,536 (nearest_narrow_), four only where there are
  // more (nearest_): a quarter of what the points hold, 0.17 MB a shape of
  // 10,000 vertices at n = 1,024.
  std::vector<Vec3> looked_from_;
  SurfaceVoronoi regions_;
  std::vector<std::uint16_t> nearest_narrow_;
  std::vector<std::uint32_t> nearest_;
  std::vector<float> distance_;
};

}  // namespace meshparticles
