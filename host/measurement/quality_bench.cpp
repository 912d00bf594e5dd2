#include "measurement/quality_bench.hpp"

#include "backends/serial_backend.hpp"
#include "particles/initial_placement.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

namespace {

QualityCase quality_case(const BenchRequest& bench, const PlannedCase& planned, const DistanceStore& distances,
                         std::size_t max_iterations, const std::function<void(const std::string&)>& on_row) {
  const SurfaceMesh& mesh = *planned.mesh;
  const std::size_t particles = planned.request.particles;
  const std::string title = planned.request.mesh + " n=" + std::to_string(particles) + " ";
  const EnergyParams energy{Potential::exp, default_sigma(Potential::exp, mesh.area(), particles)};
  QualityCase result{planned.request.mesh, mesh.vertex_count(), particles, energy.sigma, {}};

  const auto add_start = [&](const std::string& method, Init init) {
    on_row(title + method);
    const auto start = place_particles(mesh, {init, particles, 1, std::nullopt});
    result.rows.push_back({method, "", 0, false,
                           measure_quality(mesh, distances, start, energy,
                                           distance_to_nearest_particle(mesh, GeodesicMethod::fast_marching, start),
                                           /*quiet=*/true),
                           std::nullopt});
  };
  const auto add_run = [&](const std::string& method, const std::string& backend, Init init, Scheme scheme) {
    on_row(title + method + " on " + backend);
    RunRequest request;
    request.mesh_label = planned.request.mesh;
    request.particles = particles;
    request.max_iterations = max_iterations;
    request.backend.name = backend;
    request.backend.device = bench.device;
    request.backend.tuning_file = bench.tuning_file;  // the sizes `run` would take
    request.distances.kind = StoreKind::dense;         // the table the bench holds
    request.scheme = scheme;
    request.init = init;
    if (init == Init::v0) request.start_vertex = 0;
    request.quiet = true;
    const RunResult run = execute_run(mesh, plan_run(mesh, request), distances);
    result.rows.push_back(
        {method, backend, run.outcome.trace.size(), run.outcome.converged, run.quality, std::nullopt});
  };
  add_start("random", Init::random);
  add_start("farthest", Init::farthest);
  add_run("paper: v0 + sequential", serial_backend().name, Init::v0, Scheme::sequential);
  std::optional<std::size_t> serial_default;  // an index: later rows may reallocate
  for (const CheckedBackend& checked : planned.backends) {
    add_run("default", checked.name(), Init::farthest, Scheme::monotone);
    if (checked.name() == serial_backend().name) serial_default = result.rows.size() - 1;
  }
  if (serial_default) {
    const double reference = result.rows[*serial_default].quality.energy;
    for (QualityRow& row : result.rows) {
      if (row.method == "default") row.energy_vs_serial = (row.quality.energy - reference) / reference;
    }
  }
  return result;
}

}  // namespace

std::vector<QualityCase> run_quality_bench(const BenchPlan& plan, std::size_t max_iterations) {
  std::vector<QualityCase> results;
  for_each_case(plan, plan.request.backends.size() + kQualityBaselineRows,
                [&](const PlannedCase& planned, const DistanceStore& distances, const auto& on_row) {
                  results.push_back(quality_case(plan.request, planned, distances, max_iterations, on_row));
                });
  return results;
}

}  // namespace meshparticles
