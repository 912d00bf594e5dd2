#pragma once
// The solver of each GeodesicMethod: the one place that knows every
// concrete solver, so that they depend on the interface and not it on them.
#include <memory>

#include "geodesics/geodesic_solver.hpp"

namespace meshparticles {

// Its set-up on at most `threads` threads (the same solver for any number).
std::unique_ptr<GeodesicSolver> make_geodesic_solver(const SurfaceMesh& mesh, GeodesicMethod method,
                                                     unsigned threads = 1);

}  // namespace meshparticles
