#include "pipeline/run_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "backends/backend_table.hpp"
#include "backends/local_device_field_backend.hpp"
#include "common/elapsed.hpp"
#include "common/memory_limits.hpp"
#include "common/user_error.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/point_insertion.hpp"
#include "mesh/surface_walk.hpp"
#include "particles/particle_file.hpp"
#include "particles/particle_backend.hpp"
#include "pipeline/default_backend.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/sigma_check.hpp"
#include "quality/particle_sets.hpp"

namespace meshparticles {

namespace {

// The device a device backend would use, or why there is none: no usable
// OpenCL runtime, when no device was asked for (a device asked for that
// does not exist stays an error).
struct SelectedDevice {
  std::optional<DeviceDescription> device;
  std::string why_none;
};
SelectedDevice selected_device_if_any(const std::string& option) {
  try {
    return {select_device(option), ""};
  } catch (const UserError& error) {
    if (error.exit_code() == kNoRuntimeExitCode && device_request(option).text.empty()) return {{}, error.what()};
    throw;
  }
}

// The first option given that only the paper's method takes; none if none.
std::optional<std::string> paper_only_option(const RunRequest& request) {
  if (!request.backend.name.empty()) return "--backend";
  if (request.scheme) return "--scheme";
  if (request.colors) return "--colors";
  if (request.backend.weights) return "--weights";
  if (request.backend.rebuild_every) return "--rebuild-every";
  if (request.backend.work_group_size) return "--wg";
  if (request.backend.tile_size) return "--tile";
  if (request.init == Init::v0) return "--init v0";
  return std::nullopt;
}

// spread reads distances only to measure the result: local balls around
// the particles, unless the dense table is asked for.
DistancesRequest spread_distances(const DistancesRequest& request) {
  DistancesRequest spread = request;
  if (spread.kind == StoreKind::automatic) spread.kind = StoreKind::local;
  if (spread.cutoff == kDefaultCutoff) spread.cutoff = kSpreadQualityCutoff;  // --cutoff absent (or 7)
  return spread;
}

void plan_spread(const SurfaceMesh& mesh, RunPlan& plan) {
  RunRequest& request = plan.request;
  if (const auto option = paper_only_option(request)) {
    throw UserError(*option + " applies to --method paper");
  }
  plan.vertices_per_particle = request.vertices_per_particle.value_or(kSpreadVerticesPerParticle);
  plan.working_mesh = plan_working_mesh(mesh, request.particles, plan.vertices_per_particle);
  // Planned on the input: the working mesh has its area, so the same radius.
  request.distances = spread_distances(request.distances);
  plan.distances = plan_distances(mesh, request.distances, request.particles, false);
}

}  // namespace

namespace {

RunPlan plan_run_unnamed(const SurfaceMesh& mesh, const RunRequest& request) {
  RunPlan plan;
  plan.request = request;
  plan.request.distances.geodesics.quiet = request.quiet;
  if (request.particles == 0) throw UserError("-n must be at least 1");
  if (request.particles > mesh.vertex_count()) {
    throw UserError("-n " + std::to_string(request.particles) + " is more particles than the " +
                    std::to_string(mesh.vertex_count()) + " vertices of " + request.mesh_label);
  }
  if (request.method) {
    plan.method = *request.method;
    plan.method_from = "--method";
  } else if (const auto option = paper_only_option(request)) {
    plan.method = Method::paper;
    plan.method_from = *option + " implies paper";
  } else {
    plan.method = Method::spread;
    plan.method_from = "default";
  }
  if (request.start_vertex && request.init == Init::random) {
    throw UserError("--start-vertex applies to --init v0 and farthest, not random");
  }
  plan.march_method = host_march_method(request.distances.geodesics.method);
  plan.placement = {request.init, request.particles, request.seed, std::nullopt, plan.march_method};
  if (request.start_vertex) {
    plan.placement.start_vertex = surface_vertex_for_option(mesh, *request.start_vertex, "--start-vertex");
  }
  plan.energy = {request.potential,
                 request.sigma.value_or(default_sigma(request.potential, mesh.area(), request.particles))};
  check_sigma_computable(plan.energy);
  if (plan.method == Method::spread) {
    plan_spread(mesh, plan);
    return plan;
  }
  if (request.vertices_per_particle) throw UserError("--vertices-per-particle applies to --method spread");
  if (request.relax_rounds) throw UserError("--relax-rounds applies to --method spread");
  const bool default_backend = request.backend.name.empty();
  plan.distances = plan_distances(mesh, request.distances, request.particles,
                                  !default_backend && find_backend(request.backend.name).needs_dense_table);
  BackendRequest backend = request.backend;
  std::optional<Scheme> default_scheme;
  if (default_backend) {
    const bool dense = plan.distances.kind == StoreKind::dense;
    LocalBalls balls;
    if (!dense) {
      balls = {mesh.vertex_count(), expected_ball_vertices(mesh, plan.distances.radius),
               request.geodesic_given ? std::optional(request.distances.geodesics.method) : std::nullopt};
    }
    // On local distances a device is looked for only where it could pay.
    const SelectedDevice selected = dense || local_default_may_use_device(balls)
                                        ? selected_device_if_any(request.backend.device)
                                        : SelectedDevice{};
    const DefaultBackend chosen = default_paper_backend(plan.distances.kind, request.particles,
                                                        selected.device ? &*selected.device : nullptr, balls);
    backend.name = chosen.name;
    default_scheme = chosen.scheme;
    if (chosen.geodesic) plan.request.distances.geodesics.method = *chosen.geodesic;
    plan.backend_from = chosen.reason + (selected.why_none.empty() ? "" : " (" + selected.why_none + ")");
  } else {
    plan.backend_from = "--backend";
  }
  plan.request.backend.name = backend.name;
  plan.scheme = request.scheme.value_or(default_scheme.value_or(find_backend(backend.name).default_scheme));
  if (request.colors && !uses_colors(plan.scheme)) {
    throw UserError("--colors applies to --scheme colored and monotone, not " + scheme_name(plan.scheme));
  }
  plan.colors = request.colors.value_or(kDefaultColors);
  plan.backend = check_backend(backend, mesh, request.particles, plan.distances.kind == StoreKind::dense);
  if (plan.backend.device && plan.distances.kind == StoreKind::local) {  // field on balls: before any is computed
    check_local_field_device(*plan.backend.device, estimated_ball_bytes(mesh, plan.distances.radius, request.particles));
  }
  const auto sigma_warning = degenerate_sigma_warning(plan.energy, hexagonal_spacing(mesh.area(), request.particles));
  if (sigma_warning && !request.quiet) std::cerr << "meshparticles: warning: " << *sigma_warning << "\n";
  if (plan.backend.tuning_refused && !request.quiet) {
    std::cerr << "meshparticles: warning: " << plan.backend.sizes_note << "; using the built-in sizes\n";
  }
  return plan;
}

}  // namespace

RunPlan plan_run(const SurfaceMesh& mesh, const RunRequest& request) {
  // Every memory check runs while planning, before anything is computed.
  return naming_memory_failures(request.mesh_label, "planning the run", [&] { return plan_run_unnamed(mesh, request); });
}

namespace {

// spread's measurement: the distances of `working` (the mesh the
// positions are vertices of) and the quality there.
// `to_nearest`: distance_to_nearest_particle of the positions on `working`
// where the caller has it already.
void measure_spread(RunResult& result, const std::shared_ptr<RefinedMesh>& working, const std::string& label,
                    std::vector<float> to_nearest = {}) {
  const RunRequest& request = result.plan.request;
  result.working = working;
  const SurfaceMesh& measured = working->mesh;
  const auto cover_started = std::chrono::steady_clock::now();
  naming_memory_failures(label, "measuring the result", [&] {
    result.distance_to_nearest =
        to_nearest.empty() ? distance_to_nearest_particle(measured, result.plan.march_method, result.outcome.positions)
                           : std::move(to_nearest);
  });
  result.seconds.quality += seconds_since(cover_started);
  const auto measure_through = [&](const DistancesPlan& store) {
    const auto geodesics_started = std::chrono::steady_clock::now();
    const ObtainedDistances distances = naming_memory_failures(label, "computing distances", [&] {
      return obtain_distances(measured, request.distances.geodesics, store);
    });
    result.distances.kind = distances.kind;
    result.distances.table_source = distances.source;
    result.seconds.geodesics += seconds_since(geodesics_started);
    const auto quality_started = std::chrono::steady_clock::now();
    naming_memory_failures(label, "measuring the result", [&] {
      result.quality = measure_quality(measured, *distances.store, result.outcome.positions, result.plan.energy,
                                       result.distance_to_nearest, request.quiet);
    });
    result.seconds.quality += seconds_since(quality_started);
    if (const LocalDistances* balls = distances.store->local_balls()) {
      result.distances.balls = balls->statistics();
      // The balls are solved inside the quality step: count them there, not twice.
    }
  };
  measure_through(result.plan.distances);
  // A particle with no other within the default balls (a few particles on
  // a small or open surface): the balls of kSpreadWideQualityCutoff.
  if (result.quality.alone > 0 && result.plan.distances.kind == StoreKind::local &&
      request.distances.cutoff == kSpreadQualityCutoff) {
    DistancesRequest wider = request.distances;
    wider.cutoff = kSpreadWideQualityCutoff;
    measure_through(plan_distances(measured, wider, request.particles, false));
  }
}

// spread's evening step (particles/local_farthest_points) from the
// particles on the vertices of `working` (result.outcome.positions;
// `solver` is built for that mesh): each moves off the
// vertices to the centre of the largest empty circle of its neighbours on
// the surface where that widens its own gap, measured along the surface,
// and keeps the covering radius within `cover_limit`. The points it ends
// on are inserted into the working mesh as vertices.
void even_spacing(const SurfaceMesh& mesh, RunResult& result, std::shared_ptr<RefinedMesh>& working,
                  const GeodesicSolver& solver, double cover_limit) {
  const RunRequest& request = result.plan.request;
  const SurfaceMesh& surface = working->mesh;
  const SurfaceWalk walk(surface);
  std::vector<SurfaceLocation> from;
  for (const VertexId v : result.outcome.positions) {
    const std::optional<SurfaceLocation> location = walk.at_vertex(v);
    if (!location) return;  // a particle in no triangle: none moves
    from.push_back(*location);
  }
  const double d_hex = hexagonal_spacing(mesh.area(), request.particles);
  const EveningLimits limits{kSpreadEveningSweeps, d_hex, kSpreadMinGain * d_hex, kSpreadStallGain * d_hex,
                             cover_limit};
  result.evening = naming_memory_failures(request.mesh_label, "evening the spacing", [&] {
    return even_out(surface, solver, std::move(from), limits, request.quiet);
  });
  InsertedPoints inserted = insert_points(*working, mesh, result.evening->points);
  result.outcome.positions = std::move(inserted.vertices);
  working = std::make_shared<RefinedMesh>(std::move(inserted.refined));
}

// spread: the start and farthest-point optimization on the working mesh,
// then the quality there, through a store planned for that mesh.
RunResult execute_spread(const SurfaceMesh& mesh, const RunPlan& plan) {
  RunResult result;
  result.plan = plan;
  result.device = kHostDevice;
  const RunRequest& request = plan.request;
  auto particles_started = std::chrono::steady_clock::now();
  const std::string& label = request.mesh_label;
  auto working = naming_memory_failures(label, "refining the working mesh", [&] {
    return std::make_shared<RefinedMesh>(build_working_mesh(mesh, plan.working_mesh));
  });
  const std::shared_ptr<RefinedMesh> swept = working;  // the solver's mesh, kept while it lives
  const SurfaceMesh& surface = swept->mesh;
  const auto solver = make_geodesic_solver(surface, plan.march_method);
  // The input's vertices keep their ids on the working mesh.
  const double d_hex = hexagonal_spacing(mesh.area(), request.particles);
  SpreadOutcome spread = naming_memory_failures(label, "spreading the particles", [&] {
    result.start = place_particles(surface, *solver, plan.placement, request.quiet);
    return optimize_farthest_points(surface, *solver, result.start, request.max_iterations, kSpreadMinGain * d_hex,
                                    kSpreadStallGain * d_hex, request.quiet);
  });
  result.sweeps = std::move(spread.sweeps);
  result.outcome.positions = std::move(spread.positions);
  result.outcome.converged = spread.converged;
  result.stopped = spread.converged ? "converged"
                   : spread.cycled  ? "cycle"
                   : spread.stalled ? "stalled"
                                    : "max_iterations";
  // Then off the vertices: all particles pushed apart at once. Of the
  // states it passed, the most spread one whose geodesic cover is within
  // kSpreadCoverShare of the farthest start's is kept: candidates within that
  // share in straight lines, then within it over kStraightCoverMargin,
  // each inserted into the working mesh and its cover measured, the first
  // that passes kept (else the sweeps' vertices).
  const std::size_t relax_rounds = request.max_iterations == 0 ? 0 : request.relax_rounds.value_or(kSpreadRelaxRounds);
  const GeodesicMethod method = result.plan.march_method;
  const double cover_limit =
      relax_rounds == 0 ? 0.0 : kSpreadCoverShare * geodesic_cover(*solver, surface, result.start);
  const std::vector<VertexId> swept_positions = result.outcome.positions;
  result.relaxation = naming_memory_failures(label, "relaxing the spacing", [&] {
    const double swept_cover = relax_rounds == 0 ? 0.0 : geodesic_cover(*solver, surface, swept_positions);
    return relax_spacing(surface, swept_positions, d_hex, relax_rounds,
                         {cover_limit, cover_limit / kStraightCoverMargin}, swept_cover, request.quiet);
  });
  RelaxationOutcome& relaxation = result.relaxation;
  std::vector<float> kept_to_nearest;  // the kept candidate's, for the measurement
  for (std::size_t k = 0; k < relaxation.candidates.size() && relaxation.kept == relaxation.candidates.size(); ++k) {
    const RelaxationCandidate& candidate = relaxation.candidates[k];
    if (candidate.round == 0 || (k > 0 && candidate.round == relaxation.candidates[k - 1].round)) continue;
    std::vector<SurfaceLocation> moving;
    std::vector<std::size_t> movers;
    for (std::size_t i = 0; i < candidate.points.size(); ++i) {
      if (!candidate.points[i]) continue;
      moving.push_back(*candidate.points[i]);
      movers.push_back(i);
    }
    InsertedPoints inserted = insert_points(*swept, mesh, moving);
    std::vector<VertexId> positions = result.outcome.positions;
    for (std::size_t m = 0; m < movers.size(); ++m) positions[movers[m]] = inserted.vertices[m];
    std::vector<float> to_nearest = distance_to_nearest_particle(inserted.refined.mesh, method, positions);
    if (largest_finite(to_nearest) > cover_limit) {
      relaxation.passed_over_for_cover = true;
      continue;
    }
    relaxation.kept = k;
    kept_to_nearest = std::move(to_nearest);
    result.outcome.positions = std::move(positions);
    working = std::make_shared<RefinedMesh>(std::move(inserted.refined));
  }
  // Straight lines misjudged the surface (pairs on two sides of a thin part
  // that do not push each other, but are close around its tip): the
  // relaxed set is less spread than the sweeps left it, so the sweeps' set.
  bool measured = false;
  if (relaxation.kept < relaxation.candidates.size() && !result.sweeps.empty()) {
    result.seconds.particles += seconds_since(particles_started);
    measure_spread(result, working, label, std::move(kept_to_nearest));
    particles_started = std::chrono::steady_clock::now();
    measured = true;
    if (result.quality.nn_min && *result.quality.nn_min < (1 - kSpreadMinGain) * result.sweeps.back().min_spacing) {
      relaxation.kept = relaxation.candidates.size();
      relaxation.undone_for_spacing = true;
      result.outcome.positions = swept_positions;
      working = swept;
      measured = false;
    }
    kept_to_nearest.clear();
  }
  // Where the relaxation was not kept, the evening step goes on from the
  // sweeps' vertices, particle by particle.
  if (relax_rounds > 0 && relaxation.kept == relaxation.candidates.size()) {
    even_spacing(mesh, result, working, *solver, cover_limit);
    measured = false;
  }
  result.seconds.particles += seconds_since(particles_started);
  if (!measured) measure_spread(result, working, label, std::move(kept_to_nearest));
  result.seconds.total = result.seconds.particles + result.seconds.geodesics + result.seconds.quality;
  return result;
}

}  // namespace

RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan, const DistanceStore& distances) {
  // spread measures on its own mesh: a store of the input does not serve it.
  if (plan.method == Method::spread) return execute_spread(mesh, plan);
  RunResult result;
  result.plan = plan;
  const std::string& label = plan.request.mesh_label;
  const auto particles_started = std::chrono::steady_clock::now();
  naming_memory_failures(label, "moving the particles", [&] {
    const std::unique_ptr<ParticleBackend> backend = make_backend(plan.backend, mesh, distances, plan.energy);
    result.device = backend->device_name();
    result.start = place_particles(mesh, plan.placement, plan.request.quiet);
    result.outcome = run_particles(
        *backend, result.start, {plan.scheme, plan.colors, plan.request.max_iterations, plan.request.quiet},
        distances.local_balls());
  });
  result.seconds.particles = seconds_since(particles_started);

  const auto quality_started = std::chrono::steady_clock::now();
  naming_memory_failures(label, "measuring the result", [&] {
    result.distance_to_nearest =
        distance_to_nearest_particle(mesh, plan.march_method, result.outcome.positions);
    result.quality = measure_quality(mesh, distances, result.outcome.positions, plan.energy,
                                     result.distance_to_nearest, plan.request.quiet);
  });
  result.seconds.quality = seconds_since(quality_started);
  result.seconds.total = result.seconds.particles + result.seconds.quality;
  return result;
}

RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan) {
  if (plan.method == Method::spread) return execute_spread(mesh, plan);
  const ObtainedDistances distances = naming_memory_failures(plan.request.mesh_label, "computing distances", [&] {
    return obtain_distances(mesh, plan.request.distances.geodesics, plan.distances);
  });
  RunResult result = execute_run(mesh, plan, *distances.store);
  result.distances.kind = distances.kind;
  result.distances.table_source = distances.source;
  result.seconds.geodesics = distances.seconds;
  if (const LocalDistances* balls = distances.store->local_balls()) {
    result.distances.balls = balls->statistics();
    result.seconds.geodesics += result.distances.balls.seconds;  // computed during the run, on demand
  }
  result.seconds.total += distances.seconds;
  return result;
}

RunResult run_pipeline(const SurfaceMesh& mesh, const RunRequest& request) {
  return execute_run(mesh, plan_run(mesh, request));
}

}  // namespace meshparticles
