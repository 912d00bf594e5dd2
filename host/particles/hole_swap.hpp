#pragma once
// A particle taken from a crowded place and put down in the widest empty
// place near it: the farthest-point move (Schlömer et al. 2011: remove a
// point, put it back at the centre of its neighbourhood's largest hole),
// made along the surface and only within a few neighbours of where it was.
//
// Pushes and pulls move a particle a fraction of a spacing at a time and
// stop where the forces balance: a palm holding one particle too many
// beside a finger holding none (FAUST's hands after the transfer) is such a
// balance, its closest pair and its widest hole a spacing or two apart.
// One particle carried from the one to the other ends both.
#include <cstddef>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/surface_neighbours.hpp"

namespace meshparticles {

struct HoleSwapLimits {
  std::size_t max_swaps = 0;
  double spacing = 0;  // the smallest spacing wanted (mesh units): a pair closer is a crowd
  double cover = 0;    // the widest hole wanted (mesh units): one wider is a hole
  // A particle may go only into the regions of the particles within this
  // many steps of it on the surface's neighbour graph (its Voronoi
  // neighbours, theirs, ...): the swap stays local.
  std::size_t steps = 2;
};

struct HoleSwapOutcome {
  std::size_t swaps = 0;
  double smallest = 0;  // the closest neighbours' spacing after them (mesh units)
  double cover = 0;     // the widest hole after them (mesh units)
};

// Swaps `points` (points of `mesh`'s triangles; `solver` built for `mesh`)
// while the smallest spacing is under `limits.spacing` or the widest hole
// over `limits.cover`, and at most `limits.max_swaps` times. Each swap tries
// as movers the particles within `limits.steps` of the widest hole's owner
// and the two of the closest pair: each is taken out and put at the vertex
// farthest from the rest among its neighbourhood's regions. The mover kept
// is the one that leaves the least shortfall (the spacing's under its
// limit plus the hole's over its limit, each relative), where it lessens
// the shortfall and makes neither figure worse than it was. The hole is the
// largest distance of the surface's Voronoi diagram at the vertices
// (particles/surface_voronoi), whose neighbours are the movers' steps; the
// spacing is as closest_surface_pair tells it (`surface`, built for `mesh`;
// `look`, its marches' scratch). Deterministic: ties go to the lowest index.
HoleSwapOutcome swap_into_holes(const SurfaceMesh& mesh, const GeodesicSolver& solver, const SurfaceNeighbours& surface,
                                LookScratch& look, std::vector<SurfaceLocation>& points, const HoleSwapLimits& limits);

}  // namespace meshparticles
