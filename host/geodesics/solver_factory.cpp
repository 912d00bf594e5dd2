#include "geodesics/solver_factory.hpp"

#include "geodesics/dijkstra.hpp"
#include "geodesics/fast_iterative.hpp"
#include "geodesics/fast_marching.hpp"

namespace meshparticles {

std::unique_ptr<GeodesicSolver> make_geodesic_solver(const SurfaceMesh& mesh, GeodesicMethod method,
                                                     unsigned threads) {
  if (method == GeodesicMethod::dijkstra) return std::make_unique<EdgeDijkstra>(mesh);
  if (method == GeodesicMethod::fast_iterative) return std::make_unique<FastIterativeMethod>(mesh, threads);
  return std::make_unique<FastMarching>(mesh, threads);
}

}  // namespace meshparticles
