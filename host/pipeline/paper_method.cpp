#include "pipeline/paper_method.hpp"

#include <chrono>
#include <iostream>

#include "backends/backend_table.hpp"
#include "backends/local_device_field_backend.hpp"
#include "common/elapsed.hpp"
#include "common/memory_limits.hpp"
#include "common/user_error.hpp"
#include "particles/particle_backend.hpp"
#include "pipeline/default_backend.hpp"
#include "pipeline/run_pipeline.hpp"
#include "pipeline/sigma_check.hpp"

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

}  // namespace

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

void plan_paper(const SurfaceMesh& mesh, const RunRequest& request, RunPlan& plan) {
  if (request.vertices_per_particle) throw UserError("--vertices-per-particle applies to --method spread");
  if (request.relax_rounds) throw UserError("--relax-rounds applies to --method spread");
  PaperPlan& paper = plan.paper.emplace();
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
    if (chosen.geodesic) plan.geodesics.method = *chosen.geodesic;
    paper.backend_from = chosen.reason + (selected.why_none.empty() ? "" : " (" + selected.why_none + ")");
  } else {
    paper.backend_from = "--backend";
  }
  paper.scheme = request.scheme.value_or(default_scheme.value_or(find_backend(backend.name).default_scheme));
  if (request.colors && !uses_colors(paper.scheme)) {
    throw UserError("--colors applies to --scheme colored and monotone, not " + scheme_name(paper.scheme));
  }
  paper.colors = request.colors.value_or(kDefaultColors);
  paper.backend = check_backend(backend, mesh, request.particles, plan.distances.kind == StoreKind::dense);
  if (paper.backend.device && plan.distances.kind == StoreKind::local) {  // field on balls: before any is computed
    check_local_field_device(*paper.backend.device, estimated_ball_bytes(mesh, plan.distances.radius, request.particles));
  }
  const auto sigma_warning = degenerate_sigma_warning(plan.energy, hexagonal_spacing(mesh.area(), request.particles));
  if (sigma_warning && !request.quiet) std::cerr << "meshparticles: warning: " << *sigma_warning << "\n";
  if (paper.backend.tuning_refused && !request.quiet) {
    std::cerr << "meshparticles: warning: " << paper.backend.sizes_note << "; using the built-in sizes\n";
  }
}

RunResult execute_paper(const SurfaceMesh& mesh, const RunPlan& plan, const DistanceStore& distances) {
  RunResult result;
  result.plan = plan;
  const PaperPlan& paper = *plan.paper;
  const std::string& label = plan.request.mesh_label;
  const auto particles_started = std::chrono::steady_clock::now();
  naming_memory_failures(label, "moving the particles", [&] {
    const std::unique_ptr<ParticleBackend> backend = make_backend(paper.backend, mesh, distances, plan.energy);
    result.device = backend->device_name();
    result.start = place_particles(mesh, plan.placement, plan.request.quiet);
    result.outcome = run_particles(
        *backend, result.start, {paper.scheme, paper.colors, plan.request.max_iterations, plan.request.quiet},
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

}  // namespace meshparticles
