#include "particles/scheme_step.hpp"

#include <optional>
#include <vector>

namespace meshparticles {

namespace {

IterationStats monotone_iteration(ParticleBackend& backend, unsigned colors, double energy_before) {
  const std::vector<VertexId> start = backend.positions();
  unsigned attempts = 0;
  double kernel_ms = 0;
  bool kernels_timed = false;
  const auto attempt = [&](Scheme scheme, unsigned groups) -> std::optional<IterationStats> {
    IterationStats stats = backend.iterate(scheme, groups);
    ++attempts;
    if (stats.kernel_ms) kernel_ms += *stats.kernel_ms, kernels_timed = true;
    if (stats.moved == 0 || stats.energy < energy_before) return stats;
    backend.set_positions(start);  // the moves raised (or kept) the energy: undo them
    return std::nullopt;
  };
  const auto kept = [&](IterationStats stats, std::string what) {
    stats.attempts = attempts;
    stats.kept = std::move(what);
    if (kernels_timed) stats.kernel_ms = kernel_ms;
    return stats;
  };
  // Particles of one colour that interact can move together and raise the
  // energy; with twice the colours, each such pair is split with even odds.
  for (std::size_t groups = colors; groups < start.size(); groups *= 2) {
    if (auto stats = attempt(Scheme::colored, unsigned(groups))) {
      return kept(*stats, "colored K=" + std::to_string(groups));
    }
  }
  // One particle at a time, each taking its best candidate: every move
  // lowers the energy exactly by its own change.
  if (auto stats = attempt(Scheme::sequential, 1)) return kept(*stats, "sequential");
  // Only moves too small for the backend's measure of the energy remain.
  IterationStats none;
  none.energy = energy_before;
  return kept(none, "none");
}

}  // namespace

IterationStats iterate_scheme(ParticleBackend& backend, Scheme scheme, unsigned colors, double energy_before) {
  if (scheme == Scheme::monotone) return monotone_iteration(backend, colors, energy_before);
  return backend.iterate(scheme, colors);
}

std::vector<IterationStats> iterate_schemes(ParticleBackend& backend, Scheme scheme, unsigned colors,
                                            std::size_t count, double energy_before) {
  std::vector<IterationStats> done = backend.iterate_without_host(scheme, colors, count);
  if (done.empty()) done.push_back(iterate_scheme(backend, scheme, colors, energy_before));
  return done;
}

}  // namespace meshparticles
