#pragma once
// Whether two particles close in a straight line are close along the
// surface too. Two fingers side by side, an arm resting on the torso, the
// two sides of a fold: their particles are a fraction of a spacing apart
// through the air and several along the surface, and pushing them apart
// empties the fingertips and crowds the palm (FAUST's people at n = 256:
// the closest pairs and the widest holes all at the hands).
//
// From one particle the surface is marched (fast marching from its
// triangle's corners) a little past a radius; another particle's distance
// along the surface is then bounded below by its triangle's corners:
// for each corner c, d(c) - |c - particle| (the path to the particle and
// on to c is no shorter than the path to c). A pair whose bound reaches
// the radius is surely farther along the surface; one under it may not be.
#include <cstdint>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

class SurfaceNeighbours {
 public:
  // `mesh` and `solver` (built for it) must outlive this.
  SurfaceNeighbours(const SurfaceMesh& mesh, const GeodesicSolver& solver);

  // Marches from `from` far enough to tell, for any point, whether it lies
  // within `radius` along the surface.
  void look_from(const SurfaceLocation& from, double radius);

  // A lower bound of the distance along the surface from the last look's
  // point to `to`: `radius` or more where `to` is surely not within it.
  double at_least(const SurfaceLocation& to) const;

 private:
  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  double longest_edge_ = 0;
  double marched_ = 0;  // the last march's radius
  SolverScratch scratch_;
  std::vector<std::pair<VertexId, float>> within_;
  std::vector<float> distance_;  // per vertex: the last march's distance, +inf beyond it
};

}  // namespace meshparticles
