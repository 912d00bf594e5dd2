#include "pipeline/run_pipeline.hpp"

#include <chrono>

#include "common/memory_limits.hpp"
#include "common/user_error.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/paper_method.hpp"
#include "pipeline/sigma_check.hpp"
#include "pipeline/spread_method.hpp"

namespace meshparticles {

namespace {

// The checks and choices every method shares, then the method's own plan.
RunPlan plan_run_unnamed(const SurfaceMesh& mesh, const RunRequest& request) {
  RunPlan plan;
  plan.request = request;
  plan.geodesics = request.distances.geodesics;
  plan.geodesics.quiet = request.quiet;
  plan.cutoff = request.distances.cutoff_or_default();
  check_distances_request(request.distances);
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
  switch (plan.method) {
    case Method::spread: plan_spread(mesh, request, plan); break;
    case Method::paper: plan_paper(mesh, request, plan); break;
  }
  return plan;
}

}  // namespace

RunPlan plan_run(const SurfaceMesh& mesh, const RunRequest& request) {
  // Every memory check runs while planning, before anything is computed.
  return naming_memory_failures(request.mesh_label, "planning the run", [&] { return plan_run_unnamed(mesh, request); });
}

RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan, const DistanceStore& distances) {
  switch (plan.method) {
    // spread measures on its own mesh: a store of the input does not serve it.
    case Method::spread: return execute_spread(mesh, plan);
    case Method::paper: return execute_paper(mesh, plan, distances);
  }
  return {};
}

namespace {

// The distance step of a method that iterates over a store of the input:
// the planned store, obtained, and its cost added to the run's.
RunResult execute_over_input_store(const SurfaceMesh& mesh, const RunPlan& plan) {
  const ObtainedDistances distances = naming_memory_failures(plan.request.mesh_label, "computing distances", [&] {
    return obtain_distances(mesh, plan.geodesics, plan.distances);
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

}  // namespace

RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan) {
  switch (plan.method) {
    case Method::spread: return execute_spread(mesh, plan);
    case Method::paper: return execute_over_input_store(mesh, plan);
  }
  return {};
}

const SurfaceMesh& RunResult::particle_mesh(const SurfaceMesh& input) const {
  switch (plan.method) {
    case Method::spread: return spread->working->mesh;
    case Method::paper: return input;
  }
  return input;
}

RunResult run_pipeline(const SurfaceMesh& mesh, const RunRequest& request) {
  return execute_run(mesh, plan_run(mesh, request));
}

}  // namespace meshparticles
