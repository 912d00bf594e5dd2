#pragma once
// Farthest-point optimization (Schlömer, Heck and Deussen, "Farthest-point
// optimized point sets with maximized minimum distance", 2011) on the
// vertices of a mesh: each particle in turn is taken away and put back on
// the vertex farthest from all the others, if that is farther from them
// than where it was. A sweep visits the particles in index order (after
// the first, only those whose surroundings changed: see the .cpp).
// A mover lands farther from every other particle than it was from its
// nearest, so the smallest spacing of the set never shrinks while the
// close pairs are pulled apart: the particles spread evenly, which is what
// a user of this program wants, rather than lowering an energy
// (docs/ALGORITHM.md, "The default: spread").
#include <cstddef>
#include <memory>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/particle_voronoi.hpp"

namespace meshparticles {

struct SweepRecord {
  std::size_t visited = 0;  // the particles that decided again (see optimize_farthest_points)
  std::size_t moved = 0;
  double ms = 0;
  // Each particle's distance to its nearest other particle when it decided
  // (where it stayed or landed), over the sweep: the smallest and the mean.
  double min_spacing = 0, mean_spacing = 0;
};

struct SpreadOutcome {
  std::vector<VertexId> positions;
  std::vector<SweepRecord> sweeps;
  bool converged = false;  // the last sweep moved no particle
  // The last sweep ended on positions an earlier sweep ended on: a few
  // particles trading places, where fast marching's one-sided distances
  // give each move a gain (measured: 2 of 4,096 particles on a 200k mesh).
  bool cycled = false;
  // The last sweep raised the mean spacing by less than `stall_gain`: the
  // few moves left trade places within fast marching's noise (measured at
  // 10 vertices per particle: a hundred moves a sweep for 300 sweeps, the
  // mean spacing up by 0.3%, the smallest down by 4%).
  bool stalled = false;
};

// Sweeps from `start` (distinct vertices) until one moves no particle, or
// `max_sweeps` (0: the start as it is). A particle moves only where it
// gains more than `min_gain` (mesh units) of distance to its nearest: the
// distances are fast marching's, which depend a little on the order the
// regions were marched, and gains within that noise would let a few
// particles trade places forever. Deterministic: the same mesh, start and
// solver give the same bits. Unless `quiet`, a progress line per sweep.
// `diagram`: the Voronoi diagram of `start` (particle k on start[k]) by
// `solver`, as the farthest start leaves it; null to build it here.
SpreadOutcome optimize_farthest_points(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                       const std::vector<VertexId>& start, std::size_t max_sweeps, double min_gain,
                                       double stall_gain, bool quiet,
                                       std::unique_ptr<ParticleVoronoi> diagram = nullptr);

}  // namespace meshparticles
