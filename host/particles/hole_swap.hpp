#pragma once
// A particle taken from a crowded place and put down in the widest empty
// place: the farthest-point move (Schlömer et al. 2011: remove a point, put
// it back at the centre of the largest hole), made along the surface, near
// where it was or, for a hole far from the crowd, carried there a
// neighbour's place at a time.
//
// Pushes and pulls move a particle a fraction of a spacing at a time and
// stop where the forces balance: a palm holding one particle too many
// beside a finger holding none (FAUST's hands after the transfer) is such a
// balance, its closest pair and its widest hole a spacing or two apart.
// One particle carried from the one to the other ends both.
#include <cstddef>
#include <limits>
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
  double hole_step = 0;  // holes are looked for at points about this far apart (mesh units; particles/widest_hole)
  // A pair closer than this (mesh units) may be carried into a hole far off
  // where no local move helps: a carried particle's neighbours each move by
  // a spacing, and particle i then lies elsewhere than on the other shapes.
  double carry_below = 0;
  // ... or where the widest hole is wider than this (mesh units): with no
  // pair closer than carry_below, a hole about a spacing wide takes no local
  // move (the particle taken out leaves as wide a hole where it was), and a
  // crowd the evening had spread thin is then carried from all the same.
  double carry_above = std::numeric_limits<double>::infinity();
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
// - as movers the particles within `limits.steps` of the widest hole's
//   owner and the two of the closest pair: each taken out and put at the
//   vertex farthest from the rest among its neighbourhood's regions;
// - where none of those helps and the pair is closer than
//   `limits.carry_below` or the hole wider than `limits.carry_above`, each
//   of the closest pair carried into the widest
//   hole however far it is, along a shortest path of neighbours to the
//   hole's owner: each on the path takes the next one's place, the owner
//   goes into the hole (a crowd the transfer left on a palm, its hole up
//   an arm).
// The trial kept is the one that leaves the least shortfall (the spacing's
// under its limit plus the hole's over its limit, each relative), where it
// lessens the shortfall, makes the spacing no smaller and the hole no wider
// than it was or than its limit, whichever is more. The hole is
// particles/widest_hole's (at points `limits.hole_step` apart), or where
// the diagram at the vertices reads wider (hole_width takes the wider) that
// vertex: the swaps aim where the width they are judged by is. The steps
// the neighbours of the surface's Voronoi diagram at the vertices
// (particles/surface_voronoi); the spacing is as closest_surface_pair tells
// it (`surface`, built for `mesh`; `look`, its marches' scratch).
// Deterministic: ties go to the lowest index.
HoleSwapOutcome swap_into_holes(const SurfaceMesh& mesh, const GeodesicSolver& solver, const SurfaceNeighbours& surface,
                                LookScratch& look, std::vector<SurfaceLocation>& points, const HoleSwapLimits& limits);

}  // namespace meshparticles
