#pragma once
// Where particles leave a hole in a surface, and the pull that closes it.
// A packing's pushes only part pairs that are too close: nothing moves a
// particle into an empty place beside it, and a small steady pull (the
// correspondence step) can hold one open. Each point of the surface farther
// than a reach from its nearest particle draws that particle toward it: the
// particles whose Voronoi cells reach into a hole move into it (a step of
// Lloyd's toward the far part of their cells).
//
// Distances are straight lines to the nearest particle, whichever way it
// faces: the correspondence's shapes are closed bodies a spacing thick and
// more.
#include <cstdint>
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "mesh/vec3.hpp"

namespace meshparticles {

class HolePull {
 public:
  // Points of `mesh`'s surface none farther than about `step` from the
  // next: each triangle cut into equal parts with edges under `step`, the
  // parts' centroids, each standing for its part's area.
  HolePull(const SurfaceMesh& mesh, double step);

  // Per particle of `particles`: over the points farther than `reach` from
  // their nearest particle, that particle's sum of (point - particle) times
  // (1 - reach / distance) times the point's area, over `cell_area` (the
  // descent of the squared overshoots, in a cell's terms). Called again
  // with the same particles moved a little, it looks only at the points
  // that were then farther than `reach - margin` (the others are still
  // nearer than `reach` while no particle has moved `margin`): the same
  // result at a tenth of the cost.
  std::vector<Vec3> pull(const std::vector<Vec3>& particles, double reach, double margin, double cell_area);

  // The largest distance from a point to its nearest particle.
  double cover(const std::vector<Vec3>& particles) const;

  std::size_t size() const { return points_.size(); }

 private:
  std::vector<Vec3> points_;
  std::vector<double> area_;
  std::vector<Vec3> at_full_;             // the particles when every point was last looked at
  std::vector<std::uint32_t> far_;        // the points then farther than reach - margin
  double far_from_ = 0;                   // that reach - margin
};

}  // namespace meshparticles
