#pragma once
// Every ratio, angle and count by which correspond chooses a shape's pose
// (pose_choice: the trials of mesh_alignment, the body turns of body_turn,
// the relief's choice of relief_pose, the canonical form of canonical_pose,
// the medoid), each with its reason, and the one rule by which a choice
// held gives way to a challenger. The mechanisms take them from here, and
// population_doubts warns by the same numbers. Nothing here depends on the
// mechanisms: they include it, and pose_choice includes them.
#include <cstddef>

namespace meshparticles {

// The canonical form's side (canonical_pose).
struct CanonicalPoseOptions {
  // Landmarks: geodesic farthest points, whose distances to each other are
  // scaled and to every vertex place it; at most the vertex count.
  std::size_t landmarks = 200;
  // Take out the bend the form keeps (its across coordinates' quadratic
  // trend along the long axis): a bend that stretches the outer side is not
  // isometric. With the raw relief, on bent-either, none of the 8 shapes
  // bent the other way paired right without it and 1 with it; with the
  // relief's slow trend taken out too, 7 of 8 (and the 3 bent the
  // template's way, as without).
  bool straighten = true;
  // Starts of the canonical fit: the shape's principal axes onto the
  // template's in the 24 proper ways, each also turned about the long axis
  // by every `roll_degrees` below 90 (a body round in section has no
  // second axis).
  double roll_degrees = 30;
  std::size_t fit_iterations = 12;
  std::size_t fit_points = 1500;  // vertices fitted, evenly strided beyond
  // The fits whose rms lies within this ratio of the best's are told apart
  // by the relief; the others are another shape's.
  double open_ratio = 1.15;
};

struct PoseChoiceOptions {
  // --- The trials (mesh_alignment) ---
  // Iterations of each start's short affine fit (and of the rigid fit's
  // first stretch): enough to tell poses apart, not to settle them.
  std::size_t trial_iterations = 8;
  // Two poses whose turns differ by less than this are one pose (the
  // trials' ends, the runner-up, the canonical fits' ends).
  double same_pose_degrees = 30;
  // The given pose is kept where its trial ends in the best start's pose,
  // or fits within this ratio of it: shapes of one scanner often arrive
  // roughly aligned, and where the geometry barely tells poses apart, the
  // pose as given is the better guess.
  double given_pose_kept = 1.02;
  // The poses a shape's fit onto the template leaves open: those whose
  // short affine fit is within this ratio of the best's (the template's
  // relief then chooses among them, relief_pose). The bent family's wrong
  // poses fit within 1.03 to 1.09 of its right ones; FAUST's right poses up
  // to 1.15 of a turned one's. A shape's runner-up within it (its fit's, or
  // its body's agreement's) is warned of (population_doubts).
  double open_pose_ratio = 1.15;

  // --- The bodies (body_turn) ---
  // Directions at which bodies' features are compared.
  std::size_t profile_directions = 2000;
  // Rounds of choosing turns, each shape against the others' as chosen so
  // far, stopped early where none changes.
  std::size_t body_turn_rounds = 5;
  // A shape leaves the turn it has only for one whose features agree this
  // much better with the others': where two agree about as well (a shape
  // with faint features), its fit onto the template decides.
  double clearly_better_turn = 1.1;

  // --- The relief's choice (relief_pose) and its warnings ---
  // Measured at n = 256 with the detrended relief: on the one-way bent
  // families the right pose agrees 0.51 to 0.75 and the half turn 0.06 to
  // 0.34; on bent-either, shapes bent the template's way 0.59 to 0.65,
  // those bent the other way at most 0.30 in any pose (the coarse fit
  // cannot carry the template through a bend reversed); on FAUST's poses
  // the right pose 0.43 to 0.89, the runner-up 0.01 to 0.60, the arms
  // overhead 0.05 at best.
  // A runner-up's agreement within this of the chosen's is warned of.
  double close_relief = 0.1;
  // Under this no pose lays the relief: the canonical form chooses
  // (canonical_pose), and the choice is warned of.
  double weak_relief = 0.3;
  // Under this the canonical form is asked too, and takes the pose where it
  // lays the relief better; a choice under it, by either, is warned of.
  // Bodies bent the template's way agree 0.51 to 0.76 after the coarse fit.
  // Of 25 bent the other way (bent-either, 6 shapes of 2,500 vertices,
  // seeds 1 to 8) the fit took the half turn for 11 at 0.33 to 0.44; the
  // canonical form laid the relief better for 10 of them, in the true pose
  // for 7 (0.46 to 0.59). FAUST's poses under it (0.43, 0.47) agree 0.09
  // and 0.11 canonically and keep their poses. Of the 25 bent the other
  // way, 8 ended turned, chosen at margins up to 0.14.
  double sure_relief = 0.5;
  // Two fits end in the same state where the template's vertices lie less
  // than this apart on average (at unit area): then they are one pose, not
  // a runner-up, however far apart they started.
  double same_end_state = 0.05;

  // --- The canonical form (canonical_pose) ---
  CanonicalPoseOptions canonical;

  // --- The medoid (pose_choice) ---
  // A shape takes its pose onto the medoid only where that lies this much
  // nearer the population than its pose onto the template: where the two
  // are about as near, the template's is kept (and the output as it was).
  double nearer_population = 1.02;
};

// Whether a challenger whose cost (a fit's rms, a distance: lower is
// better) is `challenger` takes the place of the choice held at `held`:
// only where it costs `ratio` times less. The given pose against the best
// trial (given_pose_kept), the template's pose against the medoid's
// (nearer_population).
inline bool clearly_lower(double challenger, double held, double ratio) { return challenger * ratio < held; }

// The same for an agreement (higher is better; a correlation, which may be
// negative): where the held choice agrees at all, only where the
// challenger agrees `ratio` times more (clearly_better_turn).
inline bool clearly_higher(double challenger, double held, double ratio) {
  return !(held > 0 && challenger < ratio * held);
}

}  // namespace meshparticles
