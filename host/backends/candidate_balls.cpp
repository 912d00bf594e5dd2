#include "backends/candidate_balls.hpp"

#include <algorithm>

namespace meshparticles {

CandidateBalls::CandidateBalls(const SurfaceMesh& mesh, const LocalDistances& store)
    : mesh_(mesh), store_(store), count_(mesh.vertex_count(), 0), held_(mesh.vertex_count()) {}

void CandidateBalls::arrive(VertexId vertex, std::vector<VertexId>& arrivals) {
  if (count_[vertex]++ == 0) arrivals.push_back(vertex);
  for (const VertexId v : mesh_.one_ring(vertex)) {
    if (count_[v]++ == 0) arrivals.push_back(v);
  }
}

void CandidateBalls::depart(VertexId vertex, std::vector<VertexId>& departures) {
  if (--count_[vertex] == 0) departures.push_back(vertex);
  for (const VertexId v : mesh_.one_ring(vertex)) {
    if (--count_[v] == 0) departures.push_back(v);
  }
}

void CandidateBalls::clear_counts() { std::fill(count_.begin(), count_.end(), 0); }

std::vector<VertexId> CandidateBalls::list() const {
  std::vector<VertexId> list;
  for (VertexId v = 0; v < count_.size(); ++v) {
    if (count_[v] > 0) list.push_back(v);
  }
  return list;
}

void CandidateBalls::hold(VertexId v) {
  if (!held_[v]) held_[v] = store_.ball(v);
}

void CandidateBalls::release_all() { std::fill(held_.begin(), held_.end(), nullptr); }

}  // namespace meshparticles
