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
#include <utility>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

enum class GeodesicMethod { fast_marching, dijkstra, fast_iterative };

// "fmm" / "dijkstra" / "fim": the names used on the command line and in cache headers.
std::string method_name(GeodesicMethod method);
GeodesicMethod parse_method(const std::string& name);

// Per-thread working memory of solves. Between solves it is clean: every
// accepted flag 0, no vertex queued and every scratch distance +inf, so a
// solve that reaches few vertices costs in proportion to them, not to the
// mesh.
struct SolverScratch {
  static constexpr std::uint32_t kNotQueued = 0xFFFFFFFFu;
  std::vector<std::uint64_t> heap;      // see shortest_first_queue.hpp
  std::vector<std::uint32_t> heap_slot;  // per vertex: its index in heap, or kNotQueued
  std::vector<unsigned char> accepted;  // per vertex
  std::vector<std::uint32_t> origin;    // per vertex: the source its distance comes from (several sources)
  std::vector<VertexId> touched;        // the vertices the solve in progress gave a distance
  std::vector<VertexId> lowered;        // fast marching: those lowered by the vertex just accepted
  std::vector<double> distances;        // per vertex: the buffer of ball solves
  std::vector<std::uint64_t> ball_entries, ball_spare;  // a ball's (vertex, distance) pairs being sorted

  // Sizes the per-vertex arrays (clean) for a mesh of `vertex_count`.
  void fit(std::size_t vertex_count);
};

// The vertices within a radius of one source, in increasing id, with their
// distances from it: what a ball solve returns.
struct Ball {
  std::vector<VertexId> vertices;
  std::vector<float> distances;
  std::size_t bytes() const { return vertices.size() * (sizeof(VertexId) + sizeof(float)); }
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
  void solve(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
             double max_distance = kNoDistanceLimit) const;
  void solve(VertexId source, std::span<double> distances, SolverScratch& scratch,
             double max_distance = kNoDistanceLimit) const {
    solve(std::span<const VertexId>(&source, 1), distances, scratch, max_distance);
  }

  // The vertices within `radius` of `source` and their distances, exactly
  // the values a full solve gives them, at a cost in proportion to the ball.
  Ball solve_ball(VertexId source, double radius, SolverScratch& scratch) const;

  // The vertices within `radius` of a point between vertices, with their
  // distances (unsorted): the march starts from `corners` (a triangle's,
  // say), each at its own distance from the point in `starts`, all measuring
  // from that one point. `within` is cleared and filled.
  void solve_ball_from(std::span<const VertexId> corners, std::span<const double> starts, double radius,
                       SolverScratch& scratch, std::vector<std::pair<VertexId, float>>& within) const;

  // Lowers nearest[v] to the distance from `source` wherever that is
  // smaller, marching only where it is: a vertex no nearer to `source` than
  // to what `nearest` measures from is not expanded. What farthest-point
  // sampling needs, at a cost in proportion to the region the new sample
  // takes over.
  // `lowered`: the vertices whose nearest[v] dropped.
  void lower_nearest(VertexId source, std::span<float> nearest, SolverScratch& scratch,
                     std::vector<VertexId>& lowered) const;

  // Lowers nearest[v] wherever a march from the `rim` vertices finds it
  // shorter, each rim vertex starting at its own nearest[] and measuring
  // from the source `rim_sources[k]` it belongs to: what fills in a region
  // whose source was taken away (its nearest[] set to +inf) from the sources
  // around it, at a cost in proportion to the region. `lowered`: the
  // vertices whose nearest[] dropped; `lowered_sources`: parallel, the
  // source each now belongs to; `was`, given: parallel, each one's
  // nearest[] before (what undoes the march).
  void lower_nearest_from(std::span<const VertexId> rim, std::span<const std::uint32_t> rim_sources,
                          std::span<float> nearest, SolverScratch& scratch, std::vector<VertexId>& lowered,
                          std::vector<std::uint32_t>& lowered_sources, std::vector<float>* was = nullptr) const;

 protected:
  explicit GeodesicSolver(std::size_t vertex_count) : vertex_count_(vertex_count) {}

  // Marches from `sources` until every vertex within `max_distance` is
  // accepted, giving no vertex a distance of `bound[v]` or more (no bound
  // when empty). Expects `distances` +inf and the scratch clean wherever
  // the march goes; appends every vertex it gives a distance to
  // scratch.touched. Each vertex reached records in scratch.origin the
  // source it measures from: sources[k] is origin k, or origins[k] when
  // `origins` is given - and then each source starts at the distance it
  // already has in `distances` (noted in scratch.touched), not at 0.
  virtual void march(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                     double max_distance, std::span<const float> bound,
                     std::span<const std::uint32_t> origins = {}) const = 0;

 private:
  std::size_t vertex_count_;
};

// The largest finite value of a distance field (to the nearest of some
// sources): its covering radius, components without a source left out.
double largest_finite(std::span<const float> distances);

// |v - w| for every one-ring entry, in the order of mesh.ring_neighbors():
// the edge updates both solvers make.
std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh);

// The solver of the host's marches one at a time (farthest-point starts,
// the distance to the nearest particle, the spread's covers) in a run that
// asked for `method`. The fast iterative method pays where many balls are
// solved at once on a device; alone on the host it redoes what fast
// marching does once (3 to 11 times slower, docs/GEODESICS.md), so those
// marches use fast marching, whose stencils and update it shares and whose
// distances it reaches to within 0.002% on average.
GeodesicMethod host_march_method(GeodesicMethod method);

}  // namespace meshparticles
