#pragma once
// One iteration of any scheme on any backend. The backends run sequential,
// synchronous and colored themselves; monotone is built here from those, so
// every backend has it with the same semantics (docs/ALGORITHM.md,
// "The monotone scheme"):
//
//   an iteration of colored K; if it moved particles without lowering the
//   total energy (as the backend measures it), the particles go back and the
//   iteration is tried again with 2K colours, 4K, ... while K < n, then as
//   the sequential loop; if even that does not lower the energy, nothing
//   moves. Every kept iteration lowers the energy, so a run cannot cycle and
//   ends with no particle moving.
#include <vector>

#include "particles/particle_backend.hpp"

namespace meshparticles {

// `energy_before`: the backend's total energy at the current positions (the
// previous iteration's, or the start's).
IterationStats iterate_scheme(ParticleBackend& backend, Scheme scheme, unsigned colors, double energy_before);

// Between 1 and `count` iterations: as many as the backend runs without the
// host (ParticleBackend::iterate_without_host), else one by iterate_scheme.
std::vector<IterationStats> iterate_schemes(ParticleBackend& backend, Scheme scheme, unsigned colors,
                                            std::size_t count, double energy_before);

}  // namespace meshparticles
