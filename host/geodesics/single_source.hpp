#pragma once
// Distances from one source vertex to all vertices. A solver is built once per
// mesh, is immutable, and is shared by the threads of the all-pairs loop; each
// thread brings its own scratch space.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

enum class GeodesicMethod { fast_marching, dijkstra };

// "fmm" / "dijkstra": the names used on the command line and in cache headers.
std::string method_name(GeodesicMethod method);
GeodesicMethod parse_method(const std::string& name);

// Per-thread working memory of a solve: the priority queue and accepted flags.
struct SolverScratch {
  std::vector<std::uint64_t> heap;  // see shortest_first_queue.hpp
  std::vector<unsigned char> accepted;
};

class SingleSourceGeodesics {
 public:
  virtual ~SingleSourceGeodesics() = default;
  // Fills `distances` (one per vertex) from `source`; +inf outside its component.
  virtual void solve(VertexId source, std::span<double> distances, SolverScratch& scratch) const = 0;
};

// |v - w| for every one-ring entry, in the order of mesh.ring_neighbors():
// the edge updates both solvers make.
std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh);

std::unique_ptr<SingleSourceGeodesics> make_geodesics(const SurfaceMesh& mesh, GeodesicMethod method);

}  // namespace meshparticles
