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
  // The points of `mesh`'s surface (which must outlive this), none farther
  // than about `step` from the next: each triangle cut into equal parts
  // with edges under `step`, the parts' centroids, each standing for its
  // part's area.
  HolePull(const SurfaceMesh& mesh, double step);

  // Per particle of `particles`: over the points farther than `reach` from
  // their nearest particle, that particle's sum of (point - particle) times
  // (1 - reach / distance) times the point's area, over `cell_area` (the
  // descent of the squared overshoots, in a cell's terms). Called again
  // with the same particles moved, it looks again only at the points that
  // the particles' moves may have taken beyond `reach` (a point's distance
  // at the last full look plus how far its nearest particle has moved since):
  // the same pulls at a fraction of the cost.
  std::vector<Vec3> pull(const std::vector<Vec3>& particles, double reach, double cell_area);

  // The largest distance from a point to its nearest particle.
  double cover(const std::vector<Vec3>& particles) const;

  std::size_t size() const { return size_; }

 private:
  // Calls visit(index, point, area) for every point, in index order.
  template <typename Visit>
  void for_each_point(Visit&& visit) const;

  const SurfaceMesh& mesh_;
  std::vector<std::uint8_t> parts_;  // per triangle, its parts along an edge
  std::size_t size_ = 0;
  // At the last full look: the particles, each point's nearest and its
  // distance (rounded up).
  std::vector<Vec3> looked_from_;
  std::vector<std::uint32_t> nearest_;
  std::vector<float> distance_;
};

}  // namespace meshparticles
