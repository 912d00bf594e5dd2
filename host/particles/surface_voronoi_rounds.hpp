#pragma once
// The geodesic Voronoi diagram of points on a surface (surface_voronoi.hpp)
// by rounds of the fast iterative method's updates, on the host's threads:
// the serial reference of the device's (device_surface_voronoi,
// kernels/surface_voronoi.cl), each vertex's step written once
// (kernels/surface_voronoi_round.h), so the two give the same bits and the
// kernel is tested against it bit for bit. A round computes only the
// vertices one of whose inputs changed in the last one.
//
// The evening on the host makes its diagrams by fast marching
// (surface_voronoi), which gives them to the same accuracy, not the same
// bits (it depends on the order it accepts vertices in), in half the time
// on two threads, and agrees with the moves' own marches. With these
// rounds instead (0.30.0, the 46 corpus runs at seed 1): the diagrams 2.1x
// fast marching's time (bull at 1,024), 40 runs changed, rho down to 0.790
// (cheese at 256, from 0.834) and 3 over the cover limit: the moves' cover
// checks, by fast marching, then read another diagram than the sweep's.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/voronoi_stencils.hpp"

namespace meshparticles {

// Where the rounds of an update start (DeviceSurfaceVoronoi::update and
// SurfaceVoronoiRounds::update): the corners just seeded, and every vertex
// that kept its point and is read by an emptied one (the rims, and for
// virtual updates a little beyond), as if each had just changed.
std::vector<VertexId> rounds_start_after_moves(const VoronoiStencils& stencils, const MovedPointsReseeded& reseeded,
                                               const SurfaceVoronoi& cells);

class SurfaceVoronoiRounds {
 public:
  struct Statistics {
    std::size_t diagrams = 0;  // anew or updated
    std::size_t rounds = 0;    // rounds that changed something, over all diagrams
  };

  // The mesh's stencils, built once; `threads` (0: every core) share each
  // round's vertices.
  SurfaceVoronoiRounds(const SurfaceMesh& mesh, unsigned threads);

  // The diagram of `points` (points of the mesh's triangles), from the
  // seeds surface_voronoi starts from (seeded_surface_voronoi).
  SurfaceVoronoi diagram(std::span<const SurfaceLocation> points);

  // `cells`, the diagram of `points` before those flagged in `moved`
  // moved, brought up to date: their regions emptied, their new corners
  // seeded (reseed_moved_points), and rounds from those corners and the
  // rims. Not a diagram anew's bits: rounds go by edges, not by distance,
  // so anew a front that crosses a vertex later taken by a nearer point
  // leaves the vertices beyond it a little lower, where the update starts
  // with the unmoved regions settled.
  void update(std::span<const SurfaceLocation> points, std::span<const char> moved, SurfaceVoronoi& cells);

  const Statistics& statistics() const { return statistics_; }

 private:
  // Rounds from `voronoi` until none changes anything, the vertices in
  // `changed` taken as changed just before the first.
  void converge(std::span<const VertexId> changed, SurfaceVoronoi& voronoi);

  const SurfaceMesh& mesh_;
  unsigned threads_;
  VoronoiStencils stencils_;
  Statistics statistics_;
  // The rounds' scratch, kept between diagrams.
  std::vector<vertex_state> states_;
  std::vector<std::uint32_t> dirty_for_;  // per vertex: the round (+ 1) it is dirty for, 0 none
  std::vector<VertexId> dirty_, next_dirty_;
  std::vector<vertex_state> now_;
  std::vector<char> changed_;
};

}  // namespace meshparticles
