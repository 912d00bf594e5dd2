#include "geodesics/geodesic_solver.hpp"

#include <algorithm>
#include <limits>

#include <boost/sort/spreadsort/integer_sort.hpp>

#include "common/user_error.hpp"
#include "geodesics/dijkstra.hpp"
#include "geodesics/fast_marching.hpp"

namespace meshparticles {

std::string method_name(GeodesicMethod method) {
  return method == GeodesicMethod::fast_marching ? "fmm" : "dijkstra";
}

GeodesicMethod parse_method(const std::string& name) {
  if (name == "fmm") return GeodesicMethod::fast_marching;
  if (name == "dijkstra") return GeodesicMethod::dijkstra;
  throw UserError("unknown geodesic method '" + name + "' (use fmm or dijkstra)");
}

std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh) {
  std::vector<float> lengths(mesh.ring_neighbors().size());
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    for (std::uint32_t k = mesh.ring_offsets()[v]; k < mesh.ring_offsets()[v + 1]; ++k) {
      lengths[k] = float(distance(mesh.positions()[v], mesh.positions()[mesh.ring_neighbors()[k]]));
    }
  }
  return lengths;
}

void SolverScratch::fit(std::size_t vertex_count) {
  if (accepted.size() == vertex_count) return;
  accepted.assign(vertex_count, 0);
  heap_slot.assign(vertex_count, kNotQueued);
  origin.assign(vertex_count, 0);
  distances.assign(vertex_count, std::numeric_limits<double>::infinity());
  touched.clear();
}

void GeodesicSolver::solve(std::span<const VertexId> sources, std::span<double> distances, SolverScratch& scratch,
                           double max_distance) const {
  scratch.fit(vertex_count_);
  std::fill(distances.begin(), distances.end(), std::numeric_limits<double>::infinity());
  march(sources, distances, scratch, max_distance, {});
  // A stopped march leaves upper bounds on the vertices just beyond the
  // accepted ones: beyond the radius means +inf.
  for (const VertexId v : scratch.touched) {
    if (!scratch.accepted[v]) distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
}

Ball GeodesicSolver::solve_ball(VertexId source, double radius, SolverScratch& scratch) const {
  scratch.fit(vertex_count_);
  march(std::span<const VertexId>(&source, 1), scratch.distances, scratch, radius, {});
  std::vector<VertexId> inside;
  for (const VertexId v : scratch.touched) {
    if (scratch.accepted[v]) inside.push_back(v);
  }
  // A radix sort: std::sort was a tenth of a ball solve.
  boost::sort::spreadsort::integer_sort(inside.begin(), inside.end());
  Ball ball;
  ball.vertices = inside;
  ball.distances.reserve(inside.size());
  for (const VertexId v : inside) ball.distances.push_back(float(scratch.distances[v]));
  for (const VertexId v : scratch.touched) {  // clean again for the next solve
    scratch.distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
  return ball;
}

void GeodesicSolver::lower_nearest(VertexId source, std::span<float> nearest, SolverScratch& scratch,
                                   std::vector<VertexId>& lowered) const {
  scratch.fit(vertex_count_);
  march(std::span<const VertexId>(&source, 1), scratch.distances, scratch, kNoDistanceLimit, nearest);
  lowered.clear();
  for (const VertexId v : scratch.touched) {
    if (scratch.accepted[v] && float(scratch.distances[v]) < nearest[v]) {
      nearest[v] = float(scratch.distances[v]);
      lowered.push_back(v);
    }
    scratch.distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
}

std::unique_ptr<GeodesicSolver> make_geodesic_solver(const SurfaceMesh& mesh, GeodesicMethod method) {
  if (method == GeodesicMethod::dijkstra) return std::make_unique<EdgeDijkstra>(mesh);
  return std::make_unique<FastMarching>(mesh);
}

}  // namespace meshparticles
