#include "pipeline/spread_method.hpp"

#include <algorithm>
#include <chrono>
#include <future>
#include <iostream>

#include "common/elapsed.hpp"
#include "common/memory_limits.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "common/worker_threads.hpp"
#include "geodesics/device_balls.hpp"
#include "geodesics/local_distances.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/midpoint_refinement.hpp"
#include "mesh/point_insertion.hpp"
#include "mesh/surface_walk.hpp"
#include "particles/device_cavity_centres.hpp"
#include "particles/device_surface_voronoi.hpp"
#include "pipeline/paper_method.hpp"
#include "pipeline/run_pipeline.hpp"
#include "quality/particle_sets.hpp"

namespace meshparticles {

namespace {

// spread reads distances only to measure the result: local balls around
// the particles, unless the dense table is asked for.
DistancesRequest spread_distances(const DistancesRequest& request) {
  DistancesRequest spread = request;
  if (spread.kind == StoreKind::automatic) spread.kind = StoreKind::local;
  if (spread.cutoff_or_default() == kDefaultCutoff) spread.cutoff = kSpreadQualityCutoff;  // --cutoff absent (or 7)
  return spread;
}

}  // namespace

void plan_spread(const SurfaceMesh& mesh, const RunRequest& request, RunPlan& plan) {
  if (const auto option = paper_only_option(request)) {
    throw UserError(*option + " applies to --method paper");
  }
  SpreadPlan& spread = plan.spread.emplace();
  spread.vertices_per_particle = request.vertices_per_particle.value_or(kSpreadVerticesPerParticle);
  spread.longest_edge = request.longest_edge.value_or(kSpreadLongestEdge);
  spread.working_mesh = plan_working_mesh(mesh, request.particles, spread.vertices_per_particle, spread.longest_edge);
  if (spread.working_mesh.capped && spread.working_mesh.cap_set_by_memory.empty() && request.vertices_per_particle &&
      !request.quiet) {
    std::cerr << "meshparticles: warning: --vertices-per-particle " << format_number("%g", spread.vertices_per_particle)
              << " asks for " << format_number("%.3g", spread.vertices_per_particle * double(request.particles))
              << " vertices; the working mesh stops at "
              << refined_vertex_count(mesh, spread.working_mesh.levels) << " (the cap for time and memory: "
              << spread.working_mesh.max_vertices << ")\n";
  }
  // Planned on the input: the working mesh has its area, so the same radius.
  const DistancesRequest measured = spread_distances(request.distances);
  plan.cutoff = measured.cutoff_or_default();
  plan.distances = plan_distances(mesh, measured, request.particles, false);
  // --device: the evening's diagrams there; on a GPU the measurement's local
  // balls too, by the fast iterative method (the one with a device path)
  // unless --geodesic says otherwise. On a CPU device fim's balls took 4 to
  // 10x fast marching's on the host's cores (PoCL, bull and a 200k sphere:
  // whole runs 1.25 to 1.8x the host path's), so there only --geodesic fim
  // sends them, as the paper method's default gives the balls only to a GPU.
  // Refused now if the working mesh's buffers would not fit. A dense table
  // is solved on the host whatever the method.
  const std::uint64_t working_vertices = refined_vertex_count(mesh, spread.working_mesh.levels);
  const bool local = plan.distances.kind == StoreKind::local;
  // Without --device the evening stays on the host whatever device there
  // is (kSpreadHostByDefault says why in report.json).
  if (!request.backend.device.empty()) {
    spread.evening_device = select_device(request.backend.device);
    check_device_voronoi_fits(*spread.evening_device, working_vertices);
    spread.evening_centres_on_device =
        spread.evening_device->is_gpu() && device_has_double_precision(*spread.evening_device);
    if (local && !request.geodesic_given && spread.evening_device->is_gpu()) {
      plan.geodesics.method = GeodesicMethod::fast_iterative;
    }
  }
  if (local && plan.geodesics.method == GeodesicMethod::fast_iterative) {
    GeodesicsRequest asked = plan.geodesics;
    asked.quiet = true;  // obtain_distances warns when it finds none
    spread.measurement_device = fim_ball_device(asked);
    if (spread.measurement_device) check_device_balls_fit(*spread.measurement_device, working_vertices);
  }
}

namespace {

// The distance from each vertex of `measured` to its nearest particle
// (the cover), marched on `balls`' solver where it marches as the cover
// does (a solver's set-up is a pass over the mesh, a tenth of the
// measurement), else on one made for it.
std::vector<float> nearest_particle_distances(const RunPlan& plan, const SurfaceMesh& measured,
                                              const std::vector<VertexId>& positions, const LocalDistances* balls) {
  return balls && plan.geodesics.method == plan.march_method
             ? distance_to_nearest_particle(balls->solver(), measured, positions)
             : distance_to_nearest_particle(measured, plan.march_method, positions);
}

// spread's measurement: the distances of `working` (the mesh the
// positions are vertices of) and the quality there.
// `to_nearest`: distance_to_nearest_particle of the positions on `working`
// where the caller has it already.
// `prepared`: the store for `working` (cover_distances'), if made already.
void measure_spread(RunResult& result, const std::shared_ptr<RefinedMesh>& working, const std::string& label,
                    std::vector<float> to_nearest = {}, ObtainedDistances prepared = {}) {
  const RunRequest& request = result.plan.request;
  result.spread->working = working;
  const SurfaceMesh& measured = working->mesh;
  result.distance_to_nearest = std::move(to_nearest);
  const auto measure_through = [&](const DistancesPlan& store) {
    const auto geodesics_started = std::chrono::steady_clock::now();
    const ObtainedDistances distances =
        prepared.store ? std::move(prepared) : naming_memory_failures(label, "computing distances", [&] {
          return obtain_distances(measured, result.plan.geodesics, store);
        });
    result.distances.kind = distances.kind;
    result.distances.table_source = distances.source;
    result.seconds.geodesics += seconds_since(geodesics_started);
    const LocalDistances* balls = distances.store->local_balls();
    const auto quality_started = std::chrono::steady_clock::now();
    naming_memory_failures(label, "measuring the result", [&] {
      if (result.distance_to_nearest.empty()) {
        // The cover, unless the caller has it.
        result.distance_to_nearest = nearest_particle_distances(result.plan, measured, result.outcome.positions, balls);
      }
      result.quality = measure_quality(measured, *distances.store, result.outcome.positions, result.plan.energy,
                                       result.distance_to_nearest, request.quiet);
    });
    result.seconds.quality += seconds_since(quality_started);
    if (balls) {
      result.distances.balls = balls->statistics();
      // The balls are solved inside the quality step: count them there, not twice.
    }
  };
  measure_through(result.plan.distances);
  // A particle with no other within the default balls (a few particles on
  // a small or open surface): the balls of kSpreadWideQualityCutoff.
  if (result.quality.alone > 0 && result.plan.distances.kind == StoreKind::local &&
      result.plan.cutoff == kSpreadQualityCutoff) {
    const DistancesRequest wider{result.plan.geodesics, StoreKind::local, kSpreadWideQualityCutoff};
    measure_through(plan_distances(measured, wider, request.particles, false));
  }
}

// A relaxed candidate's nearest_particle_distances. Where the measurement's
// balls would march them, their store is made now and left in `store`
// for the measurement of the candidate kept (its set-up then counted in
// the particles' time, where the cover check needs it).
std::vector<float> cover_distances(const RunPlan& plan, const SurfaceMesh& measured,
                                   const std::vector<VertexId>& positions, ObtainedDistances& store) {
  if (plan.distances.kind == StoreKind::local && plan.geodesics.method == plan.march_method) {
    store = obtain_distances(measured, plan.geodesics, plan.distances);
  }
  return nearest_particle_distances(plan, measured, positions, store.store ? store.store->local_balls() : nullptr);
}

// The evening's diagrams on a device (run --device), set up (its stencils,
// buffers and program: 0.1 s at 40k vertices, a tenth of a run at 1,024)
// beside the farthest start and the sweeps, which use one core, where the
// run may use more; at its first use where it may not. No future where no
// device is asked.
struct EveningDevices {
  std::unique_ptr<DeviceSurfaceVoronoi> diagrams;
  std::unique_ptr<DeviceCavityCentres> moves;  // where SpreadPlan::evening_centres_on_device
};

std::future<EveningDevices> set_up_evening_device(const RunPlan& plan, const SurfaceMesh& surface) {
  if (!plan.spread->evening_device) return {};
  const bool beside = cores_or(plan.request.distances.geodesics.threads) > 1;
  return std::async(beside ? std::launch::async : std::launch::deferred,
                    [&surface, device = *plan.spread->evening_device,
                     centres = plan.spread->evening_centres_on_device] {
                      EveningDevices devices;
                      devices.diagrams = std::make_unique<DeviceSurfaceVoronoi>(surface, device);
                      if (centres) devices.moves = std::make_unique<DeviceCavityCentres>(surface, device);
                      return devices;
                    });
}

// spread's evening step (particles/local_farthest_points) from the
// particles at `from`, points of `swept` (the working mesh the sweeps ran
// on; `solver` is built for it): each moves
// to the centre of the largest empty circle of its neighbours on
// the surface where that widens its own gap, measured along the surface,
// and keeps the covering radius within `cover_limit`. The points it ends
// on are inserted into `swept` as vertices: that mesh becomes `working`.
void even_spacing(const SurfaceMesh& mesh, RunResult& result, std::vector<SurfaceLocation> from,
                  const std::shared_ptr<RefinedMesh>& swept, std::shared_ptr<RefinedMesh>& working,
                  const GeodesicSolver& solver, double cover_limit,
                  std::future<EveningDevices>& device_setup) {
  const RunRequest& request = result.plan.request;
  const SurfaceMesh& surface = swept->mesh;
  const double d_hex = hexagonal_spacing(mesh.area(), request.particles);
  const EveningLimits limits{kSpreadEveningSweeps,     d_hex,       kSpreadEveningMinGain * d_hex,
                             kSpreadStallGain * d_hex, cover_limit, kSpreadSwapBelow * d_hex,
                             kSpreadSwapRounds,        true};
  std::optional<EveningOutcome>& evening = result.spread->evening;
  const EveningDevices devices = device_setup.valid() ? device_setup.get() : EveningDevices{};
  if (devices.diagrams) result.device = devices.diagrams->device_name();
  evening = naming_memory_failures(request.mesh_label, "evening the spacing", [&] {
    return even_out(surface, solver, std::move(from), limits, request.distances.geodesics.threads, request.quiet,
                    {devices.diagrams.get(), devices.moves.get()});
  });
  InsertedPoints inserted = insert_points(*swept, mesh, evening->points);
  result.outcome.positions = std::move(inserted.vertices);
  working = std::make_shared<RefinedMesh>(std::move(inserted.refined));
}

// Where this machine's memory cut the working mesh short, the particles
// differ from a run on a machine with more: said, not silent.
void warn_of_memory_cap(const RunPlan& plan, const RefinedMesh& working) {
  const WorkingMeshPlan& planned = plan.spread->working_mesh;
  if (planned.cap_set_by_memory.empty() || plan.request.quiet) return;
  std::cerr << "meshparticles: warning: " << plan.request.mesh_label << ": the working mesh stops at "
            << working.mesh.vertex_count() << " vertices, short of the resolution asked (no edge over "
            << format_number("%g", plan.spread->longest_edge) << " spacings"
            << (plan.spread->vertices_per_particle > 0
                    ? ", " + format_number("%g", plan.spread->vertices_per_particle) + " vertices per particle"
                    : std::string())
            << "): half the memory usable here (set by "
            << planned.cap_set_by_memory << ") holds " << planned.max_vertices
            << "; with more memory the particles differ (report.json: working_mesh.vertex_cap_set_by)\n";
}

}  // namespace

RunResult execute_spread(const SurfaceMesh& mesh, const RunPlan& plan) {
  RunResult result;
  result.plan = plan;
  result.device = kHostDevice;
  SpreadDetails& details = result.spread.emplace();
  const RunRequest& request = plan.request;
  auto particles_started = std::chrono::steady_clock::now();
  const std::string& label = request.mesh_label;
  auto working = naming_memory_failures(label, "refining the working mesh", [&] {
    return std::make_shared<RefinedMesh>(build_working_mesh(mesh, plan.spread->working_mesh));
  });
  details.working_mesh_cut_short = plan.spread->working_mesh.capped || working->stopped_at_cap;
  if (details.working_mesh_cut_short) warn_of_memory_cap(plan, *working);
  const std::shared_ptr<RefinedMesh> swept = working;  // the solver's mesh, kept while it lives
  const SurfaceMesh& surface = swept->mesh;
  const unsigned threads = cores_or(request.distances.geodesics.threads);
  const auto solver = make_geodesic_solver(surface, plan.march_method, threads);
  std::future<EveningDevices> evening_device = set_up_evening_device(plan, surface);
  // The input's vertices keep their ids on the working mesh.
  const double d_hex = hexagonal_spacing(mesh.area(), request.particles);
  const std::size_t relax_rounds = request.max_iterations == 0 ? 0 : request.relax_rounds.value_or(kSpreadRelaxRounds);
  std::future<double> start_cover;  // the farthest start's geodesic cover, for the relaxation
  SpreadOutcome spread = naming_memory_failures(label, "spreading the particles", [&] {
    Placement start = place_particles_with_diagram(surface, *solver, plan.placement, request.quiet);
    result.start = std::move(start.vertices);
    // One march, beside the sweeps (they use one core) where the run may
    // use more: 5 s of the 1M sphere's run at 100,000 on 2 threads.
    if (relax_rounds > 0) {
      start_cover = std::async(threads > 1 ? std::launch::async : std::launch::deferred,
                               [&] { return geodesic_cover(*solver, surface, result.start); });
    }
    return optimize_farthest_points(surface, *solver, result.start, request.max_iterations, kSpreadMinGain * d_hex,
                                    kSpreadStallGain * d_hex, request.quiet, std::move(start.diagram));
  });
  details.sweeps = std::move(spread.sweeps);
  result.outcome.positions = std::move(spread.positions);
  result.outcome.converged = spread.converged;
  details.stopped = spread.converged ? "converged"
                   : spread.cycled  ? "cycle"
                   : spread.stalled ? "stalled"
                                    : "max_iterations";
  // Then off the vertices: all particles pushed apart at once. Of the
  // states it passed, the most spread one whose geodesic cover is within
  // kSpreadCoverShare of the farthest start's is kept: candidates within that
  // share in straight lines, then within it over kStraightCoverMargin,
  // each inserted into the working mesh and its cover measured, the first
  // that passes kept (else the sweeps' vertices).
  const double cover_limit = relax_rounds == 0 ? 0.0 : kSpreadCoverShare * start_cover.get();
  details.cover_limit = cover_limit;
  const std::vector<VertexId> swept_positions = result.outcome.positions;
  details.relaxation = naming_memory_failures(label, "relaxing the spacing", [&] {
    // Where the straight lines it pushes by already misjudge the sweeps'
    // set, decided before the first round, not after the last.
    const double swept_spacing = details.sweeps.empty() ? 0.0 : details.sweeps.back().min_spacing;
    // The sweeps' geodesic cover scales the rounds' straight ones: one march
    // over the working mesh, made only where rounds will run (most real
    // models skip them: on the corpus 36 runs of 46).
    std::vector<Vec3> swept_at;
    for (const VertexId v : swept_positions) swept_at.push_back(surface.positions()[v]);
    const bool rounds_run = relax_rounds > 0 && !straight_lines_misjudge(swept_at, swept_spacing, threads);
    const double swept_cover = rounds_run ? geodesic_cover(*solver, surface, swept_positions) : 0.0;
    return relax_spacing(surface, swept_positions, d_hex, relax_rounds,
                         {cover_limit, cover_limit / kStraightCoverMargin}, swept_cover, request.quiet, swept_spacing,
                         /*stop_early=*/true, request.distances.geodesics.threads);
  });
  RelaxationOutcome& relaxation = details.relaxation;
  std::vector<float> kept_to_nearest;  // the kept candidate's, for the measurement
  ObtainedDistances kept_store;        // and its store, where cover_distances made one
  // How much longer than straight lines the geodesic cover of a candidate
  // passed over proved: the most of any.
  double widening = 1;
  // Whether `candidate`, inserted into the working mesh, holds the cover
  // limit there; if so it is the run's.
  const auto covered = [&](const RelaxationCandidate& candidate) {
    InsertedPoints inserted = insert_points(*swept, mesh, candidate.points);
    auto inserted_mesh = std::make_shared<RefinedMesh>(std::move(inserted.refined));
    std::vector<VertexId> positions = std::move(inserted.vertices);
    ObtainedDistances store;
    std::vector<float> to_nearest = cover_distances(result.plan, inserted_mesh->mesh, positions, store);
    const double cover = largest_finite(to_nearest);
    if (cover > cover_limit) {
      relaxation.passed_over_for_cover = true;
      if (candidate.cover > 0) widening = std::max(widening, cover / candidate.cover);
      return false;
    }
    kept_to_nearest = std::move(to_nearest);
    kept_store = std::move(store);
    result.outcome.positions = std::move(positions);
    working = std::move(inserted_mesh);
    return true;
  };
  for (std::size_t k = 0; k < relaxation.candidates.size() && relaxation.kept == relaxation.candidates.size(); ++k) {
    const RelaxationCandidate& candidate = relaxation.candidates[k];
    if (candidate.round == 0 || (k > 0 && candidate.round == relaxation.candidates[k - 1].round)) continue;
    if (covered(candidate)) relaxation.kept = k;
  }
  // Every candidate over the limit: straight lines missed a hole (igea at
  // 20,000: 0.765 d_hex straight, 0.84 along the surface, over the limit's
  // 0.817). The most spread state passed on the way whose straight cover,
  // widened as much, is within the limit is tried once more (igea: round
  // 125's 0.707, against the evening's rho 0.836).
  if (relaxation.kept == relaxation.candidates.size() && relaxation.passed_over_for_cover) {
    const RelaxationCandidate* state = fallback_state(relaxation, widening, cover_limit);
    if (state && covered(*state)) {
      relaxation.candidates.push_back(*state);
      relaxation.kept = relaxation.candidates.size() - 1;
    }
  }
  // Straight lines misjudged the surface (pairs on two sides of a thin part
  // that do not push each other, but are close around its tip): the
  // relaxed set is not more spread than the evening would leave the
  // sweeps' set, so that set, and the evening.
  bool measured = false;
  if (relaxation.kept < relaxation.candidates.size() && !details.sweeps.empty()) {
    result.seconds.particles += seconds_since(particles_started);
    measure_spread(result, working, label, std::move(kept_to_nearest), std::move(kept_store));
    particles_started = std::chrono::steady_clock::now();
    measured = true;
    if (result.quality.nn_min && *result.quality.nn_min < kRelaxedOverSweeps * details.sweeps.back().min_spacing) {
      relaxation.kept = relaxation.candidates.size();
      relaxation.undone_for_spacing = true;
      result.outcome.positions = swept_positions;
      working = swept;
      measured = false;
    }
    kept_to_nearest.clear();
  }
  // Where the relaxation was not kept, the evening step goes on from the
  // sweeps' vertices, particle by particle; where the relaxed set was kept
  // but measures less spread than the evening leaves most shapes, from the
  // relaxed set (knot2 at 256, seed 2: rho 0.845 relaxed, 0.910 evened).
  if (relax_rounds > 0 && relaxation.kept == relaxation.candidates.size()) {
    const SurfaceWalk walk(surface);
    std::vector<SurfaceLocation> from;
    for (const VertexId v : swept_positions) from.push_back(walk.at_vertex(v));
    even_spacing(mesh, result, std::move(from), swept, working, *solver, cover_limit, evening_device);
    measured = false;
  } else if (measured && result.quality.rho && *result.quality.rho < kSpreadEveningAfterRelaxationBelow) {
    even_spacing(mesh, result, relaxation.candidates[relaxation.kept].points, swept, working, *solver, cover_limit,
                 evening_device);
    measured = false;
  }
  result.seconds.particles += seconds_since(particles_started);
  if (!measured) measure_spread(result, working, label, std::move(kept_to_nearest));
  result.seconds.total = result.seconds.particles + result.seconds.geodesics + result.seconds.quality;
  return result;
}

}  // namespace meshparticles
