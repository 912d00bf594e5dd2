#include "geodesics/geodesic_solver.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "common/user_error.hpp"

namespace meshparticles {

std::string method_name(GeodesicMethod method) {
  switch (method) {
    case GeodesicMethod::fast_marching: return "fmm";
    case GeodesicMethod::dijkstra: return "dijkstra";
    case GeodesicMethod::fast_iterative: return "fim";
  }
  return "fmm";
}

GeodesicMethod parse_method(const std::string& name) {
  if (name == "fmm") return GeodesicMethod::fast_marching;
  if (name == "dijkstra") return GeodesicMethod::dijkstra;
  if (name == "fim") return GeodesicMethod::fast_iterative;
  throw UserError("unknown geodesic method '" + name + "' (use fmm, fim or dijkstra)");
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

namespace {

// Sorts (vertex << 32 | payload) entries by vertex: an LSD radix sort over
// only the bits a vertex id of this mesh can have, in passes of at most 11
// bits (a count table that stays in L1). Comparison sorts were a tenth of
// a ball solve.
void sort_by_vertex(std::vector<std::uint64_t>& entries, std::vector<std::uint64_t>& spare, std::size_t vertex_count) {
  const int bits = int(std::bit_width(std::max<std::size_t>(vertex_count, 2) - 1));
  const int passes = (bits + 10) / 11;
  const int width = (bits + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t(1) << width) - 1;
  spare.resize(entries.size());
  std::vector<std::uint32_t> count(std::size_t(1) << width);
  for (int pass = 0; pass < passes; ++pass) {
    const int shift = 32 + pass * width;
    std::fill(count.begin(), count.end(), 0);
    for (const std::uint64_t e : entries) ++count[(e >> shift) & mask];
    std::uint32_t at = 0;
    for (auto& c : count) at += std::exchange(c, at);
    for (const std::uint64_t e : entries) spare[count[(e >> shift) & mask]++] = e;
    entries.swap(spare);
  }
}

}  // namespace

Ball GeodesicSolver::solve_ball(VertexId source, double radius, SolverScratch& scratch) const {
  scratch.fit(vertex_count_);
  march(std::span<const VertexId>(&source, 1), scratch.distances, scratch, radius, {});
  // Each vertex inside with its float distance in one word, so that one
  // sort orders both; the scratch is made clean again for the next solve.
  std::vector<std::uint64_t>& inside = scratch.ball_entries;
  inside.clear();
  for (const VertexId v : scratch.touched) {
    if (scratch.accepted[v]) {
      const float d = float(scratch.distances[v]);
      std::uint32_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      inside.push_back((std::uint64_t(v) << 32) | bits);
    }
    scratch.distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
  sort_by_vertex(inside, scratch.ball_spare, vertex_count_);
  Ball ball;
  ball.vertices.resize(inside.size());
  ball.distances.resize(inside.size());
  for (std::size_t k = 0; k < inside.size(); ++k) {
    ball.vertices[k] = VertexId(inside[k] >> 32);
    const auto bits = std::uint32_t(inside[k]);
    std::memcpy(&ball.distances[k], &bits, sizeof bits);
  }
  return ball;
}

void GeodesicSolver::solve_ball_from(std::span<const VertexId> corners, std::span<const double> starts, double radius,
                                     SolverScratch& scratch, std::vector<std::pair<VertexId, float>>& within) const {
  scratch.fit(vertex_count_);
  std::vector<std::uint32_t> one_point(corners.size(), 0);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (!std::isinf(scratch.distances[corners[k]])) continue;  // a corner given twice: its first start
    scratch.distances[corners[k]] = starts[k];
    scratch.touched.push_back(corners[k]);
  }
  march(corners, scratch.distances, scratch, radius, {}, one_point);
  within.clear();
  for (const VertexId v : scratch.touched) {
    if (scratch.accepted[v]) within.emplace_back(v, float(scratch.distances[v]));
    scratch.distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
}

namespace {

// After a march bounded by `nearest`: lowers nearest[v] where the march
// found v nearer, lists those vertices (and, given `sources`, the source
// each now measures from), and leaves the scratch clean.
void keep_nearer(std::span<float> nearest, SolverScratch& scratch, std::vector<VertexId>& lowered,
                 std::vector<std::uint32_t>* sources, std::vector<float>* was = nullptr) {
  lowered.clear();
  if (sources) sources->clear();
  if (was) was->clear();
  for (const VertexId v : scratch.touched) {
    if (scratch.accepted[v] && float(scratch.distances[v]) < nearest[v]) {
      if (was) was->push_back(nearest[v]);
      nearest[v] = float(scratch.distances[v]);
      lowered.push_back(v);
      if (sources) sources->push_back(scratch.origin[v]);
    }
    scratch.distances[v] = std::numeric_limits<double>::infinity();
    scratch.accepted[v] = 0;
  }
  scratch.touched.clear();
}

}  // namespace

void GeodesicSolver::lower_nearest(VertexId source, std::span<float> nearest, SolverScratch& scratch,
                                   std::vector<VertexId>& lowered) const {
  scratch.fit(vertex_count_);
  march(std::span<const VertexId>(&source, 1), scratch.distances, scratch, kNoDistanceLimit, nearest);
  keep_nearer(nearest, scratch, lowered, nullptr);
}

void GeodesicSolver::lower_nearest_from(std::span<const VertexId> rim, std::span<const std::uint32_t> rim_sources,
                                        std::span<float> nearest, SolverScratch& scratch,
                                        std::vector<VertexId>& lowered,
                                        std::vector<std::uint32_t>& lowered_sources,
                                        std::vector<float>* was) const {
  scratch.fit(vertex_count_);
  for (const VertexId v : rim) {
    scratch.distances[v] = nearest[v];
    scratch.touched.push_back(v);
  }
  march(rim, scratch.distances, scratch, kNoDistanceLimit, nearest, rim_sources);
  keep_nearer(nearest, scratch, lowered, &lowered_sources, was);
}

double largest_finite(std::span<const float> distances) {
  double largest = 0;
  for (const float d : distances) {
    if (std::isfinite(d)) largest = std::max(largest, double(d));
  }
  return largest;
}

GeodesicMethod host_march_method(GeodesicMethod method) {
  return method == GeodesicMethod::fast_iterative ? GeodesicMethod::fast_marching : method;
}

}  // namespace meshparticles
