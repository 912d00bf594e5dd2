#pragma once
// Distances from a set of source vertices to the vertices around them. A
// solver is built once per mesh, is immutable, and is shared by the threads
// of the all-pairs loop; each thread brings its own scratch space. Several
// sources and a stopping distance are what on-demand local distances and
// multi-source starts need (as pmp-library's geodesics(mesh, seeds, maxdist)).
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

enum class GeodesicMethod { fast_marching, dijkstra };

// "fmm" / "dijkstra": the names used on the command line and in cache headers.
std::string method_name(GeodesicMethod method);
GeodesicMethod parse_method(const std::string& name);

// Per-thread working memory of a solve: the priority queue, accepted flags,
// and each vertex's nearest source (fast marching).
struct SolverScratch {
  std::vector<std::uint64_t> heap;  // see shortest_first_queue.hpp
  std::vector<unsigned char> accepted;
  std::vector<std::uint32_t> origin;
};

inline constexpr double kNoDistanceLimit = std::numeric_limits<double>::infinity();

class GeodesicSolver {
 public:
  virtual ~GeodesicSolver() = default;
  // Fills `distances` (one per vertex) with the distance to the nearest of
  // `sources` (each at 0). The solve stops once every vertex within
  // `max_distance` is final: those values are exactly what an unlimited
  // solve gives, and every vertex beyond it, or in a component without a
  // source, is +inf.
  virtual void solve(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                     double max_distance = kNoDistanceLimit) const = 0;

  void solve(VertexId source, std::span<double> distances, SolverScratch& scratch,
             double max_distance = kNoDistanceLimit) const {
    solve(std::span<const VertexId>(&source, 1), distances, scratch, max_distance);
  }
};

// |v - w| for every one-ring entry, in the order of mesh.ring_neighbors():
// the edge updates both solvers make.
std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh);

std::unique_ptr<GeodesicSolver> make_geodesic_solver(const SurfaceMesh& mesh, GeodesicMethod method);

}  // namespace meshparticles
