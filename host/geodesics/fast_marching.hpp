#pragma once
// Fast marching on a triangulated surface (Kimmel & Sethian) with a
// point-source triangle update: from accepted X and Y, the source is placed in
// the triangle's plane at distances d(X), d(Y) (on the far side of XY), and C
// gets its straight-line distance when that line crosses edge XY. The update
// is exact for a flat mesh and far more accurate than the planar-wavefront
// update near the source, where wavefronts are most curved. Obtuse corners
// use unfolded virtual triangles (see triangle_stencils.hpp).
#include "geodesics/geodesic_solver.hpp"
#include "geodesics/triangle_stencils.hpp"

namespace meshparticles {

class FastMarching : public GeodesicSolver {
 public:
  // Its set-up (the triangle stencils) on at most `threads` threads.
  explicit FastMarching(const SurfaceMesh& mesh, unsigned threads = 1);

 protected:
  void march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
             double max_distance, std::span<const float> bound,
             std::span<const std::uint32_t> origins = {}) const override;

 private:
  template <bool kOneSource>
  void march_from(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                  double max_distance, std::span<const float> bound, std::span<const std::uint32_t> origins) const;

  // Where a vertex's edges, triangle updates and virtual updates start, side
  // by side: the march reads all three for each vertex it accepts, in an
  // order the memory cannot foresee, and from one record they cost one
  // cache miss, not three (vertex V + 1 holds the ends).
  struct UpdateStarts {
    std::uint32_t ring, triangles, virtuals, unused;
  };

  const SurfaceMesh& mesh_;
  std::vector<float> edge_lengths_;  // parallel to mesh.ring_neighbors()
  TriangleStencils stencils_;        // its offsets moved into starts_
  std::vector<UpdateStarts> starts_;
};

}  // namespace meshparticles
