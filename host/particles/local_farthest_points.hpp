#pragma once
// Farthest-point optimization off the vertices, among surface neighbours:
// the evening step after the sweeps on vertices (docs/ALGORITHM.md,
// "Evening"). A sweep visits every particle and moves it to the centre of
// its cavity: the point of its region of the geodesic Voronoi diagram
// farthest along the surface from the particles around it
// (particles/cavity_centre, through their geodesic balls), if that is
// farther from them than where it stands. So no particle is ever kept or
// dropped because of another pair, and two parts facing each other through
// the air never push (distances are along the surface). The balls read a
// pair a little differently from its two ends, so a sweep can narrow the
// smallest spacing: the particles kept are those of the sweep where it was
// widest.
//
// Sweeps end where every particle stands at its cavity's centre, which can
// hold a pair no move of either end widens (at a tip, across a thin part).
// Then one of the pair is taken to the widest hole and the sweeps run
// again from there: a swap, kept where it widens the smallest spacing. The
// place it left can be a hole wider than the cover limit that no move
// closes (each widens its own gap, and the particle beside it may have it
// at its back): each sweep first draws that particle toward it.
//
// Vertices cap farthest-point optimization: a particle can only stand where
// a vertex is, up to an edge from the true centre, which costs about a
// tenth of a spacing at 24 vertices per particle. Off the vertices that
// cap is gone, at no finer mesh.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/surface_walk.hpp"
#include "particles/device_cavity_centres.hpp"
#include "particles/device_surface_voronoi.hpp"

namespace meshparticles {

struct EveningSweep {
  std::size_t moved = 0;
  std::size_t drawn = 0;          // of them, moved toward a hole before the sweep's moves (where the evening started over the cover limit)
  double smallest = 0, mean = 0;  // each particle's distance along the surface to the nearest particle around it, after the sweep
  double cover = 0;               // the geodesic covering radius before the sweep (mesh units)
  double longest = 0;             // the longest move kept, straight (mesh units)
  double ms = 0;
};

// Where the sweeps' Voronoi diagrams were computed, and what they took.
struct EveningDiagrams {
  std::string device;    // empty: the host's surface_voronoi; else the device's name
  std::size_t count = 0;
  std::size_t rounds = 0;  // on a device: the rounds that changed something, all diagrams
  double seconds = 0;      // all the diagrams, seeding to result
};

// One swap tried after the sweeps: a particle of the closest pair taken to
// the widest hole, and the evening run again from there.
struct EveningSwap {
  std::uint32_t particle = 0;
  double smallest = 0;      // the smallest spacing the evening from there kept (mesh units)
  double cover = 0;         // and its cover (mesh units)
  std::size_t sweeps = 0;
  double ms = 0;
  bool kept = false;        // wider than before, the cover within the limit
};

// Where the moves' cavity centres were found, and what they took.
struct EveningMoves {
  std::string device;  // empty: the host's cavity_centre; else the device's name
  double seconds = 0;  // every set's proposals (regions read, centres, decisions), wherever found
  std::size_t launches = 0;   // on a device: one an independent set
  std::size_t sets_on_host = 0;  // on a device: sets left to the host (their balls outgrew its largest buffer)
  double device_seconds = 0;  // on a device: its uploads, kernels and reads
};

struct EveningOutcome {
  std::vector<SurfaceLocation> points;  // in the caller's order
  std::vector<EveningSweep> sweeps;     // the first evening's
  double cover = 0;                     // the points' geodesic covering radius (mesh units)
  EveningDiagrams diagrams;
  EveningMoves moves;
  std::size_t kept_sweep = 0;           // the first evening's sweep it kept (0: the start)
  std::vector<EveningSwap> swaps;       // in the order tried
};

struct EveningLimits {
  std::size_t max_sweeps = 0;
  double d_hex = 0;       // the hexagonal spacing, mesh units
  double min_gain = 0;    // a move must widen its particle's gap by more (mesh units)
  double stall_gain = 0;  // sweeps stop when one raises the mean spacing by less (mesh units)
  double cover = 0;       // no move takes the covering radius over this (mesh units)
  double swap_below = 0;  // swaps run while the smallest spacing is under this (mesh units)
  std::size_t swap_rounds = 0;  // at most this many swaps kept
  // Each sweep first draws in the regions over `cover`, and a sweep within
  // it is kept before one over it (spread); else a region over it is only
  // held from widening (correspond's gap sweeps, whose limit is their
  // start's own cover).
  bool hold_cover = false;
};

// From `start` (points of `mesh`'s triangles; `solver` is built for
// `mesh`), sweeps until one moves nothing, raises the mean spacing by less
// than `limits.stall_gain`, or `limits.max_sweeps` have run. A move must
// gain more than `limits.min_gain`, and must leave the region it came from
// within `limits.cover` of it (where the start is wider, as a swap leaves
// its hole, a region over it may narrow but not widen). With
// `limits.hold_cover`, each sweep first moves each particle whose region
// is over the limit toward the region's farthest vertex, where that brings
// the region within it and does not make the closest pair, and a sweep
// within the limit is kept before one over it.
// Each sweep's particles go in independent sets, each set's moves judged
// on `threads` threads (0: every core). Deterministic: the same inputs give
// the same bits, for any number of threads. Returns the points of the sweep
// (or the start) whose smallest spacing is widest. Then, while that is
// under `limits.swap_below` and for at most `limits.swap_rounds` rounds,
// each of the two particles whose gaps are smallest is tried in the widest
// hole, the evening run again from there; of those whose smallest spacing
// is wider with the cover within `limits.cover`, the widest is kept (none:
// the swaps stop). Each particle's geodesic
// ball is kept for the evening (about 45 bytes a vertex of `mesh`). Unless
// `quiet`, a progress line.
// With `device.diagrams` (built for `mesh`), each sweep's Voronoi diagram
// is the device's (device_surface_voronoi), not the host's
// surface_voronoi; with `device.moves`, each independent set's cavity
// centres are the device's (device_cavity_centres): the same bits.
struct EveningDevice {
  DeviceSurfaceVoronoi* diagrams = nullptr;
  DeviceCavityCentres* moves = nullptr;
};
EveningOutcome even_out(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> start,
                        const EveningLimits& limits, unsigned threads, bool quiet, EveningDevice device = {});

}  // namespace meshparticles
