#pragma once
// spread, the default run method: farthest-point optimization on a working
// mesh (the input refined), then the relaxation or the evening step off its
// vertices, the kept points inserted as vertices, and the quality measured
// there (docs/ALGORITHM.md, "The default: spread"). No backend, no table:
// it reads distances only to measure its result. plan_run and execute_run
// (pipeline/run_pipeline.hpp) call it for Method::spread.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mesh/midpoint_refinement.hpp"
#include "mesh/surface_mesh.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/farthest_point_optimization.hpp"
#include "particles/local_farthest_points.hpp"
#include "particles/spacing_relaxation.hpp"
#include "particles/spread_working_mesh.hpp"

namespace meshparticles {

// spread measures its result through balls of this many hexagonal spacings
// (unless --cutoff says otherwise): every nearest neighbour of a spread set
// lies within (they are 0.7 to 1 spacing apart), and balls of 3 cost four
// times as much, a fifth of a run on real models. The energy it reports
// sums the pairs within it only.
inline constexpr double kSpreadQualityCutoff = 1.5;
// ... and through balls of this many where a particle has no other within
// those (a few particles on a small or open surface: 4 on the committed
// patch are 1.86 spacings apart).
inline constexpr double kSpreadWideQualityCutoff = 3.0;
// spread: a particle moves only to gain more than this many hexagonal
// spacings of distance to its nearest (below it, fast marching's noise).
inline constexpr double kSpreadMinGain = 1e-3;
// spread's evening: a particle moves only to gain more than this many
// hexagonal spacings. The small moves count once each is read to a few
// thousandths (0.26.0: balls from the corners' fans): at 10^-3 against
// 3·10^-3 the 46 corpus runs at seed 1 reach rho 0.899 against 0.892 at
// the median and nn_cv 0.019 against 0.020, for twice the moves
// (docs/ALGORITHM.md, "Evening").
inline constexpr double kSpreadEveningMinGain = 1e-3;
// spread stops when a sweep raises the mean spacing by less than this many
// hexagonal spacings.
inline constexpr double kSpreadStallGain = 1e-4;
// Why spread's evening stays on the host unless --device asks (report.json's
// `device_from`, as the paper method's `backend_from`): the device's
// diagrams are label-correcting rounds, not fast marching's bits, and the
// evening's moves follow them, so a default on the device would make the
// particles depend on the machine (on an H200 it paid 0.90 to 0.96x at
// n = 4,096 where an evening ran, 1.2 to 1.8x below: docs/PERFORMANCE.md).
inline constexpr const char* kSpreadHostByDefault =
    "default: the evening on the host, the same particles on every machine";
// spread: rounds of relaxation after the sweeps (docs/ALGORITHM.md,
// "Relaxation"); it stops earlier where its radius stops growing.
inline constexpr std::size_t kSpreadRelaxRounds = 150;
// spread: where the relaxed set is kept but measures a rho under this, the
// evening goes on from it (docs/ALGORITHM.md, "Evening": on the 46 corpus
// runs at seeds 1 and 2, 3 of the 14 kept relaxed sets, 0.845 to 0.892,
// end 0.910 to 0.925; a well relaxed set keeps its nn_cv, which the evening
// would double: the sphere at 1,024 0.0024 -> 0.0051).
inline constexpr double kSpreadEveningAfterRelaxationBelow = 0.9;
// spread: sweeps of the evening step at most (docs/ALGORITHM.md, "Evening");
// it stops earlier when one moves nothing or stalls (measured on 8 CGAL
// models at n = 1,024: 7 to 12 sweeps).
inline constexpr std::size_t kSpreadEveningSweeps = 40;
// spread's evening: where its smallest spacing ends under this many
// hexagonal spacings, a particle of the closest pair is tried in the widest
// hole and the evening run again, at most kSpreadSwapRounds times kept
// (docs/ALGORITHM.md, "Evening": a pair at a tip or across a thin part that
// neither end can widen; man at 256: 0.842 -> 0.920).
inline constexpr double kSpreadSwapBelow = 0.87;
inline constexpr std::size_t kSpreadSwapRounds = 4;
// spread's relaxation keeps no state whose covering radius is over this
// share of the farthest start's (farthest-point sampling is nearly optimal
// for cover; issue 29 asks no more than 1.1 times it).
inline constexpr double kSpreadCoverShare = 1.1;
// spread keeps a relaxed set only where its measured smallest spacing is at
// least this many times the sweeps' last: else the evening, which runs
// instead, would most likely do better. It reaches 1.04 at the median (the
// 46 corpus cases at seeds 1 and 2, 0.21.0 with smoothed facing: 157
// evenings from 0.98 to 1.08 at the tenths); sets kept were 1.007 to 1.21
// (fandisk at 256 kept at 0.805 where the evening gives 0.822, bunny00 at
// 1,024 at 0.805 where it gives 0.864).
inline constexpr double kRelaxedOverSweeps = 1.04;
// The relaxation measures cover in straight lines, shorter than geodesics:
// its second candidate is the most spread state within the share above
// divided by this margin (measured: straight covers 1.2 to 1.7% under fast
// marching's on the committed meshes), tried where the first's geodesic
// cover is over the share.
inline constexpr double kStraightCoverMargin = 1.03;

// What plan_run decides for spread alone (RunPlan::spread).
struct SpreadPlan {
  double vertices_per_particle = 0;  // asked of the working mesh
  double longest_edge = 0;           // asked of the working mesh, in hexagonal spacings
  WorkingMeshPlan working_mesh;
  // --device given: the evening's Voronoi diagrams on it
  // (particles/device_surface_voronoi); else on the host.
  std::optional<DeviceDescription> evening_device;
  // And its moves' cavity centres (particles/device_cavity_centres): where
  // that device is a GPU with double precision. On a CPU device they stay
  // on the host, whose cores it shares: there the same centres took 1.15 to
  // 1.94x the host's time (PoCL, docs/PERFORMANCE.md).
  bool evening_centres_on_device = false;
  // Where the measurement's local balls are solved: with the fast iterative
  // method (--device's default, or --geodesic fim) the device
  // fim_ball_device finds (geodesics/device_balls); else, with none, or on
  // the dense table (--distances dense), the host.
  std::optional<DeviceDescription> measurement_device;
};

// What a spread run yields beside every method's result (RunResult::spread).
struct SpreadDetails {
  // The mesh the particles live on, the input refined; the result's
  // positions, start and distance_to_nearest are on it.
  std::shared_ptr<const RefinedMesh> working;
  // The working mesh as built (before points are inserted) has fewer
  // vertices than asked: its cap cut it short (WorkingMeshPlan says what set it).
  bool working_mesh_cut_short = false;
  std::vector<SweepRecord> sweeps;
  RelaxationOutcome relaxation;  // the kept candidate's points are inserted into `working`, unless evened
  // Where no relaxed set is kept, or the kept one measured a rho under
  // kSpreadEveningAfterRelaxationBelow (none under --relax-rounds 0): its
  // points are inserted into `working`.
  std::optional<EveningOutcome> evening;
  // The geodesic cover the relaxation's kept state and the evening hold:
  // kSpreadCoverShare of the farthest start's (0 under --relax-rounds 0).
  double cover_limit = 0;
  std::string stopped;                    // converged, cycle, stalled or max_iterations (SpreadOutcome)
};

struct RunRequest;
struct RunPlan;
struct RunResult;

// spread's part of plan_run, after the checks common to every method:
// refuses the paper's options, plans the working mesh and the store that
// measures the result.
void plan_spread(const SurfaceMesh& mesh, const RunRequest& request, RunPlan& plan);

// spread's execute_run: the start and the sweeps on the working mesh, the
// relaxation or the evening step, then the quality there, through a store
// planned for that mesh.
RunResult execute_spread(const SurfaceMesh& mesh, const RunPlan& plan);

}  // namespace meshparticles
