#include "measurement/bench.hpp"

#include <algorithm>
#include <chrono>

#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "particles/scheme_step.hpp"

namespace meshparticles {

namespace {

// The timed iterations are the first ones from the start (the warm-ups run
// first and the positions are then put back). The direct-sum backends do the
// same work in every iteration; the field backends' work follows the moves,
// which are most frequent right after the start, so their figure includes
// the busiest iterations, with the particles moved beside it.
void time_iterations(ParticleBackend& backend, const std::vector<VertexId>& start, const BenchSettings& settings,
                     BenchRow& row) {
  backend.set_positions(start);
  double energy = backend.total_energy();
  for (std::size_t w = 0; w < settings.warmups; ++w) {
    energy = iterate_scheme(backend, row.scheme, settings.colors, energy).energy;
  }
  backend.set_positions(start);
  energy = backend.total_energy();
  std::vector<double> samples;
  double kernel_sum = 0, sum = 0, moved_sum = 0;
  bool kernels_timed = false;  // device backends time their kernels
  while (samples.size() < settings.iterations) {
    // As a run iterates: several iterations at once where the backend runs
    // them without the host, each taking its share of their wall time.
    const auto begin = std::chrono::steady_clock::now();
    const std::vector<IterationStats> done = iterate_schemes(
        backend, row.scheme, settings.colors, std::min(kIterationsWithoutHost, settings.iterations - samples.size()),
        energy);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count() /
                      double(done.size());
    for (const IterationStats& stats : done) {
      energy = stats.energy;
      samples.push_back(ms);
      sum += ms;
      if (stats.kernel_ms) {
        kernel_sum += *stats.kernel_ms;
        kernels_timed = true;
      }
      moved_sum += double(stats.moved);
    }
  }
  row.mean_ms = sum / double(settings.iterations);
  row.moved_mean = moved_sum / double(settings.iterations);
  row.timing = summarize_timings(samples);
  if (kernels_timed) row.kernel_ms = kernel_sum / double(settings.iterations);
}

BenchCase bench_case(const std::string& mesh_name, const SurfaceMesh& mesh, const DistanceStore& distances,
                     std::size_t particles, const std::vector<CheckedBackend>& backends,
                     const BenchSettings& settings, const std::function<void(const std::string&)>& on_row) {
  BenchCase result{mesh_name, mesh.vertex_count(), particles, {}};
  const EnergyParams energy{Potential::exp, default_sigma(Potential::exp, mesh.area(), particles)};
  const std::vector<VertexId> start = place_particles(mesh, {Init::farthest, particles, 1, std::nullopt});
  for (const CheckedBackend& checked : backends) {
    on_row(mesh_name + " n=" + std::to_string(particles) + " " + checked.name());
    BenchRow row;
    row.backend = checked.name();
    row.scheme = checked.device ? settings.device_scheme : Scheme::sequential;  // serial rows: the CPU loop
    if (checked.kernel) {
      row.sizes = checked.kernel->sizes_text();
      row.sizes_from = checked.sizes_from;
    }
    const auto backend = make_backend(checked, mesh, distances, energy);
    time_iterations(*backend, start, settings, row);
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace

std::vector<BenchCase> run_bench(const BenchPlan& plan, const BenchSettings& settings) {
  std::vector<BenchCase> results;
  for_each_case(plan, plan.request.backends.size(),
                [&](const PlannedCase& planned, const DistanceStore& distances, const auto& on_row) {
                  results.push_back(bench_case(planned.request.mesh, *planned.mesh, distances,
                                               planned.request.particles, planned.backends, settings, on_row));
                });
  return results;
}

}  // namespace meshparticles
