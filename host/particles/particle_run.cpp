#include "particles/particle_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "common/progress.hpp"
#include "geodesics/local_distances.hpp"
#include "particles/scheme_step.hpp"

namespace meshparticles {

RunOutcome run_particles(ParticleBackend& backend, std::span<const VertexId> start, const RunSettings& settings,
                         const LocalDistances* balls) {
  RunOutcome outcome;
  backend.set_positions(start);
  outcome.initial_energy = backend.total_energy();
  ProgressLine progress("particles", settings.max_iterations, settings.quiet);
  const std::optional<DeviceTraffic> traffic_before = backend.traffic();
  while (outcome.trace.size() < settings.max_iterations && !outcome.converged) {
    const auto started = std::chrono::steady_clock::now();
    const auto balls_before = balls ? std::optional(balls->statistics()) : std::nullopt;
    const double energy_before = outcome.trace.empty() ? outcome.initial_energy : outcome.trace.back().energy;
    const std::size_t wanted = std::min(kIterationsWithoutHost, settings.max_iterations - outcome.trace.size());
    const std::vector<IterationStats> done =
        iterate_schemes(backend, settings.scheme, settings.colors, wanted, energy_before);
    // Iterations run without the host share their launch's wall time.
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count() /
                      double(done.size());
    for (const IterationStats& stats : done) {
      IterationRecord record{stats.energy, stats.moved, ms, stats.kernel_ms, stats.attempts > 1 ? stats.kept : "",
                             std::nullopt, std::nullopt};
      char detail[128];
      const int length = std::snprintf(detail, sizeof detail, "moved %zu  energy %.6g  %.2f ms/iteration",
                                       stats.moved, stats.energy, ms);
      if (balls_before) {  // local distances: one iteration at a time
        const LocalDistances::Statistics balls_after = balls->statistics();
        record.balls_solved = balls_after.balls_computed - balls_before->balls_computed;
        record.ball_ms = 1000.0 * (balls_after.seconds - balls_before->seconds);
        std::snprintf(detail + length, sizeof detail - std::size_t(length), "  %zu balls", *record.balls_solved);
      }
      outcome.trace.push_back(std::move(record));
      progress.update(outcome.trace.size(), detail);
      if (stats.moved == 0) outcome.converged = true;
    }
  }
  if (const std::optional<DeviceTraffic> traffic_after = backend.traffic()) {
    outcome.traffic = DeviceTraffic{traffic_after->launches - traffic_before->launches,
                                    traffic_after->host_waits - traffic_before->host_waits};
  }
  const std::size_t done = outcome.trace.size();
  char summary[128];
  std::snprintf(summary, sizeof summary, "%s, energy %.6g",
                outcome.converged ? "converged" : "iteration limit reached",
                done ? outcome.trace.back().energy : outcome.initial_energy);
  progress.finish(summary);
  outcome.positions = backend.positions();
  return outcome;
}

}  // namespace meshparticles
