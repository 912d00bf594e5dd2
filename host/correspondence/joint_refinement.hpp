#pragma once
// After the transfer, every shape's particles move together (issue 31's
// joint optimization, in the spirit of ShapeWorks' particle system): on each
// shape a sampling step pushes closer-than-spacing pairs apart along the
// surface, as the template's own run spread them, and a correspondence step
// pulls each shape, in the population's aligned frame, towards the model of
// the others (the gradient of the regularised ensemble entropy, log det(C +
// alpha I), which shrinks the shape-to-shape variation that few shapes
// share, and leaves the true modes alone). The transfer's particles are
// consistent but crowded; the sampling alone would even each shape out on
// its own and lose the correspondence; together they do both.
//
// Soft disks at a fixed radius jam before they pack as evenly as a shape's
// own run (nn_cv 0.02 against 0.002), so the refinement ends with the
// packing of the own run's relaxation (particles/packing_relaxation: pairs
// pushed apart for a radius that grows while it can), the correspondence
// step beside it, its weight fading to a share held to the end. A shape
// whose packing the held step keeps from closing a hole is let go to
// close it on its own. Where the packing leaves the population less spread
// than the iterations did (the median shape's smallest spacing over all
// pairs lower: on a body, the sides of a hand, which do not face each
// other, squeezed together, and pushes across the air between limbs), it is
// undone, as the own run keeps the sweeps over a relaxation less spread.
#include <cstddef>
#include <vector>

#include "correspondence/shape_share.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/surface_walk.hpp"

namespace meshparticles {

// One shape's particles while they move: where each lies on its mesh (on
// the process that owns the shape; another's has no mesh and no particles).
struct ShapeParticles {
  const SurfaceMesh* mesh = nullptr;
  std::vector<SurfaceLocation> at;
};

struct JointRefinementOptions {
  std::size_t iterations = 200;
  // The correspondence step's weight against the sampling step's (0: each
  // shape evened out on its own, and the correspondence drifts).
  double correspondence_weight = 0.1;
  // Then the packing, while the correspondence step's weight fades, over
  // its first 50 rounds, to `packing_hold` of the iterations' (0: each
  // shape packs on its own, the evenest, and the model is less compact:
  // docs/CORRESPONDENCE.md).
  bool pack = true;
  double packing_hold = 0.2;
  // Then each shape keeps only as much of its evening as keeps its closest
  // pair this many hexagonal spacings apart (hold_back_evening; 0: as near
  // the transfer's places as its holes and the other shapes allow; 1: the
  // refinement's places).
  double even_enough = 0.75;
};

struct JointRefinementRecord {
  // Per iteration: the mean overlap of closer-than-spacing pairs (each
  // shape's sampling objective, in its hexagonal spacings) and the mean
  // length of the correspondence step (in the aligned frame's spacings).
  std::vector<double> overlap, correspondence_step;
  // The packing: per round, the mean over shapes of the radius held (the
  // smallest spacing, in hexagonal spacings) and the correspondence step's
  // length; the rounds it took.
  std::vector<double> packing_spacing, packing_correspondence_step;
  std::size_t packing_rounds = 0;
  std::size_t packing_released = 0;  // shapes let go to pack on their own (a hole held open)
  bool packing_undone = false;       // the packing left the shapes less spread: the iterations' places kept
  // Per shape, the share of each particle's move from the transfer that
  // hold_back_evening kept (in tenths; 1: the refinement's places), and the
  // sweeps of moves that only widen a gap that it then took (0: none, the
  // shape even enough), and the particles it then carried from a crowd
  // into a hole (particles/hole_swap).
  std::vector<double> evening_kept;
  std::vector<std::size_t> gap_sweeps;
  std::vector<std::size_t> hole_swaps;
};

// The iterations, then the packing (each a stage a resume starts from):
// they move every owned shape's particles, all shapes holding `particles`
// particles, row i the same particle; what the population's step needs of
// the others comes through `share`. Deterministic, and the same for any
// number of processes and threads. Unless `quiet`, a progress line.
void iterate_jointly(std::vector<ShapeParticles>& shapes, std::size_t particles, const JointRefinementOptions& options,
                     ShapeShare& share, JointRefinementRecord& record, bool quiet);
void pack_jointly(std::vector<ShapeParticles>& shapes, std::size_t particles, const JointRefinementOptions& options,
                  ShapeShare& share, JointRefinementRecord& record, bool quiet);

// The widest hole `particles` leave on `mesh` (particles/widest_hole, as
// wide as hole_width takes it), in hexagonal spacings, as hold_back_evening's swaps measure each shape's (the
// template's: what they hold every shape's holes to).
double widest_hole_spacings(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& particles);

// Each owned shape evened out no further than it needs. Evening each shape
// on its own moves particle i differently on every shape: on the ellipsoid
// families at n = 1,024 that, not the transfer, made most of its spread
// across them. So every particle is taken back along its move from
// `transferred` (its place after the transfer) to where the refinement left
// it, to the least share of that move (in tenths) at which the shape is
// still even enough: its closest pair (straight) `options.even_enough`
// hexagonal spacings apart or more, no hole over 5% wider than the evened
// shape's, and its particles no more than twice as far (squared) from the
// mean of the other shapes' (aligned as the model aligns them) as the
// evened shape's: where the transfer was wrong (a shape a few degrees
// turned), the refinement's correction is kept. The refinement's places
// where no share is. A shape still closer than even enough, or with a hole
// over kSwapHole times `template_hole` (widest_hole_spacings of the
// template's own run), then takes particles from its crowds into its holes
// (one for each kParticlesPerSwap particles at most). With no iterations
// (`options.iterations` 0) the transfer's places stay.
void hold_back_evening(std::vector<ShapeParticles>& shapes, const std::vector<std::vector<SurfaceLocation>>& transferred,
                       std::size_t particles, double template_hole, const JointRefinementOptions& options,
                       ShapeShare& share, JointRefinementRecord& record);

}  // namespace meshparticles
