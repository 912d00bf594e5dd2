#pragma once
// After farthest-point optimization, the particles leave the vertices: all
// of them are pushed apart at once, on the surface, until no pair is closer
// than a radius that grows while it can be reached (soft disks whose radius
// grows, as Lubachevsky and Stillinger grow hard disks into a packing).
// Farthest-point optimization settles where no single particle can widen
// the smallest gap; moving them together can (docs/ALGORITHM.md,
// "Relaxation").
//
// The pushes and the growing radius are particles/packing_relaxation's:
// straight-line distances between particles that face the same way.
#include <cstddef>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/packing_relaxation.hpp"

namespace meshparticles {

// The relaxation is not run where the start's smallest straight spacing,
// between any two particles, is under this share of its smallest geodesic
// one: some pair faces another through the air or across a fold, and the
// straight lines it pushes by misjudge the surface. On 10 CGAL models at
// n = 256 to 4,096 (25 runs) no relaxation under 0.75 was kept (most ran
// 100 or 150 rounds and were then thrown away); the committed meshes start
// at 0.999 to 1, fandisk, a CAD part whose relaxation is kept, at 0.755.
// Pairs facing away (the two sides of a thin part) count too, though they
// do not push each other (0.23.0; to 0.22.0 only facing pairs counted): on
// the corpus's 46 runs at seeds 1 and 2, 42 relaxations ran and 27 were
// thrown away (10.7 s of their 15.9 s); now 20 run and 6 are thrown away
// (3.4 s of 8.2 s), the same particles but for fandisk at 256 seed 2 (kept at
// 0.843, now skipped: the evening's 0.822).
inline constexpr double kRelaxationStraightShare = 0.7;

// Whether straight lines misjudge the surface between the particles at
// `at`: two of them, facing each other or not, are under
// kRelaxationStraightShare of `geodesic_spacing` apart in a straight line
// (false where that is 0). The relaxation is not run there.
bool straight_lines_misjudge(const std::vector<Vec3>& at, double geodesic_spacing, unsigned threads);

// A state the relaxation passed: the most spread one within a cover limit.
struct RelaxationCandidate {
  std::vector<SurfaceLocation> points;
  double spacing = 0;      // the smallest straight-line spacing
  double cover = 0;        // straight_cover, scaled as at the start (relax_spacing)
  std::size_t round = 0;   // 0: the start (then `points` are its vertices)
};

// Why the rounds ended.
enum class RelaxationStop {
  not_run,       // no rounds asked, no pair within reach, or skipped_for_straight
  max_rounds,    // ran all the rounds asked
  stalled,       // the smallest spacing stopped growing (kPatienceRounds)
  no_candidate,  // no state more spread than the start by kHopelessAfter rounds
  squeezed,      // none yet, and the even-density rounds held a pair far under the start's spacing
  out_of_reach,  // none yet, and the growth could not pass the start's spacing by then
  uncovered,     // none yet, and a state more spread than the start left holes far over the cover limit
};
const char* relaxation_stop_name(RelaxationStop stop);

struct RelaxationOutcome {
  double start_spacing = 0, start_cover = 0;
  // Per cover limit given, in its order: the state with the largest
  // smallest spacing whose straight cover is within it.
  std::vector<RelaxationCandidate> candidates;
  // The states that were, as they came, the most spread within the widest
  // limit (their spacing rising), the candidates among them: where the
  // candidates' geodesic covers prove over the limit, an earlier one may
  // be within it.
  std::vector<RelaxationCandidate> passed;
  std::vector<double> round_spacings;  // the smallest straight spacing after each round, mesh units
  double ms = 0;
  // Set by the caller: the candidate it kept (candidates.size(): none, the
  // start), and whether a candidate was passed over for its geodesic cover.
  std::size_t kept = 0;
  bool passed_over_for_cover = false;
  bool undone_for_spacing = false;  // the kept candidate's geodesic smallest spacing was under the sweeps' own
  bool skipped_for_straight = false;  // not run: kRelaxationStraightShare
  RelaxationStop stopped = RelaxationStop::not_run;
};

// Where every candidate's geodesic cover proved over `cover_limit`, at most
// `widening` times its straight one: of the states the rounds passed, the
// most spread whose straight cover, widened as much, is within the limit,
// unless a candidate was that state already (then none: it failed). None
// where no state qualifies.
const RelaxationCandidate* fallback_state(const RelaxationOutcome& outcome, double widening, double cover_limit);

// The largest straight-line distance from a vertex of `mesh` to the nearest
// particle on a vertex facing its way: the covering radius, measured as the
// relaxation measures its candidates' (a few tens of milliseconds on a
// million vertices).
double straight_cover(const SurfaceMesh& mesh, const std::vector<VertexId>& particles);

// From particles on the vertices `start` of `mesh`, at most `max_rounds`
// rounds (0: the start as it is): first kFoamRounds pushing for a radius a
// little over the hexagonal spacing `d_hex`, which evens out the density
// (every particle is pushed from all sides, so no vacancy stays), then
// rounds whose radius grows from the smallest spacing reached. Every few
// rounds the state is a candidate for each of `cover_limits`, its straight
// cover scaled by the start's `start_geodesic_cover` over its straight one
// (0: unscaled); `passed` keeps the states on the way. No round is run
// (`skipped_for_straight`) where the start's smallest straight spacing
// (between any two particles, facing or not) is under
// kRelaxationStraightShare of `start_geodesic_spacing` (0: no such
// test). The rounds stop early
// (`stopped`) where no state more spread than the start has come by
// kHopelessAfter rounds, or none has come yet and the even-density rounds
// squeezed a pair far under the start's spacing (squeezed), the growing
// radius could not pass it by then (out_of_reach), or a state more spread
// than the start left holes far over every cover limit (uncovered; none of
// the three where not `stop_early`, which tests use to see the rounds they
// skip). On `threads` threads (0: every core). Deterministic: the same mesh
// and start give the same bits, whatever the threads. Unless `quiet`, a
// progress line.
RelaxationOutcome relax_spacing(const SurfaceMesh& mesh, const std::vector<VertexId>& start, double d_hex,
                                std::size_t max_rounds, const std::vector<double>& cover_limits,
                                double start_geodesic_cover, bool quiet, double start_geodesic_spacing = 0,
                                bool stop_early = true, unsigned threads = 1);

}  // namespace meshparticles
