#pragma once
// The iteration loop every backend shares: iterate until the iteration limit
// or until an iteration moves no particle, recording a trace.
#include <optional>
#include <string>
#include <vector>

#include "particles/particle_backend.hpp"

namespace meshparticles {

class LocalDistances;

// The iteration limit of a run when --iterations is absent.
constexpr std::size_t kDefaultMaxIterations = 500;

// How many iterations a backend that can may run before the host looks at
// them (the trace, the progress line, the limit): one launch and one read
// on the field backend. A run stops after the first that moves nothing.
constexpr std::size_t kIterationsWithoutHost = 16;

struct RunSettings {
  Scheme scheme = Scheme::colored;
  unsigned colors = 8;
  std::size_t max_iterations = kDefaultMaxIterations;
  bool quiet = false;  // no progress line
};

struct IterationRecord {
  double energy = 0;
  std::size_t moved = 0;
  double ms = 0;  // wall time of the iteration
  std::optional<double> kernel_ms;
  std::string redone_as;  // monotone: what was kept when the first attempt was undone; else empty
  // Local distances: balls solved while the iteration ran (by every thread),
  // and the milliseconds the particle loop spent solving or waiting for balls.
  std::optional<std::size_t> balls_solved;
  std::optional<double> ball_ms;
};

struct RunOutcome {
  double initial_energy = 0;
  std::vector<IterationRecord> trace;
  bool converged = false;  // an iteration moved no particle
  // Device backends: the launches and host waits of the iterations.
  std::optional<DeviceTraffic> traffic;
  std::vector<VertexId> positions;
};

// With `balls` (the local store the backend reads), each iteration's record
// also says how many balls were solved while it ran and how long the
// particles waited on them.
RunOutcome run_particles(ParticleBackend& backend, std::span<const VertexId> start, const RunSettings& settings,
                         const LocalDistances* balls = nullptr);

}  // namespace meshparticles
