#pragma once
// The one interface every backend implements (the serial reference and its
// field twin; the naive, tiled and field OpenCL backends). A backend holds
// the particle positions; one call of iterate() is one iteration of the
// chosen scheme.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

struct IterationStats {
  std::size_t moved = 0;
  double energy = 0;                 // total pair energy after the iteration
  std::optional<double> kernel_ms;  // update kernels (field: and its field updates), from profiling events (device backends)
  // monotone: the attempts this iteration took, and what the kept one was
  // ("colored K=32", "sequential", or "none" when no attempt lowered the energy).
  unsigned attempts = 1;
  std::string kept;
};

// What a device backend asked of its device: kernel launches, and the times
// the host stopped to wait for it (blocking reads and writes, finish).
struct DeviceTraffic {
  std::size_t launches = 0;
  std::size_t host_waits = 0;
};

// The device a backend that runs on the host reports, in report.json and
// bench tables, where an OpenCL backend reports its device's name.
inline constexpr const char* kHostDevice = "serial";

class ParticleBackend {
 public:
  virtual ~ParticleBackend() = default;
  // kHostDevice, or the OpenCL device's name.
  virtual std::string device_name() const = 0;
  virtual void set_positions(std::span<const VertexId> positions) = 0;
  virtual std::vector<VertexId> positions() = 0;
  // sequential: every particle in index order; synchronous: one sub-step of
  // all particles from one snapshot; colored: `colors` sub-steps, group
  // index % colors after group. (monotone is iterate_scheme's, on top.)
  virtual IterationStats iterate(Scheme scheme, unsigned colors) = 0;
  // Total pair energy sum_{i<j} w(d(p_i, p_j)) of the current positions.
  virtual double total_energy() = 0;
  // Up to `count` iterations of `scheme`, the same as iterate_scheme would
  // make them, without the host between them; ends after the first that
  // moves nothing. Empty where this backend cannot (most): the caller then
  // iterates one at a time (iterate_schemes, scheme_step.hpp).
  virtual std::vector<IterationStats> iterate_without_host(Scheme /*scheme*/, unsigned /*colors*/,
                                                           std::size_t /*count*/) {
    return {};
  }
  // Device backends: what they asked of the device so far.
  virtual std::optional<DeviceTraffic> traffic() const { return std::nullopt; }
};

// The number of colour groups a scheme updates one after the other.
inline unsigned sub_steps(Scheme scheme, unsigned colors) { return scheme == Scheme::colored ? colors : 1; }

// The particles one iteration on the host moves: `sequential_sweep()`, or
// `synchronous_step(color, groups)` for each colour group in turn.
template <typename Sweep, typename Step>
std::size_t host_iteration_moves(Scheme scheme, unsigned colors, Sweep sequential_sweep, Step synchronous_step) {
  if (scheme == Scheme::sequential) return sequential_sweep();
  const unsigned groups = sub_steps(scheme, colors);
  std::size_t moved = 0;
  for (unsigned color = 0; color < groups; ++color) moved += synchronous_step(color, groups);
  return moved;
}

}  // namespace meshparticles
