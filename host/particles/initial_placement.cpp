#include "particles/initial_placement.hpp"

#include <limits>
#include <numeric>

#include "common/random.hpp"

namespace meshparticles {

namespace {

std::vector<VertexId> distinct_random_vertices(std::size_t vertex_count, std::size_t count, std::uint64_t seed) {
  // The first `count` steps of a Fisher-Yates shuffle.
  std::vector<VertexId> vertices(vertex_count);
  std::iota(vertices.begin(), vertices.end(), VertexId{0});
  SplitMix64 random(seed);
  for (std::size_t i = 0; i < count; ++i) std::swap(vertices[i], vertices[i + random.below(vertex_count - i)]);
  vertices.resize(count);
  return vertices;
}

// Each new sample is the vertex farthest from all samples so far (ties: the
// smaller id). Another component is infinitely far, so each gets a sample
// before any gets a second.
std::vector<VertexId> farthest_point_samples(const DistanceStore& distances, std::size_t count, VertexId first) {
  const std::size_t vertex_count = distances.vertex_count();
  std::vector<float> nearest(vertex_count, std::numeric_limits<float>::infinity());
  std::vector<bool> taken(vertex_count, false);
  std::vector<VertexId> samples;
  samples.reserve(count);
  VertexId next = first;
  while (true) {
    samples.push_back(next);
    taken[next] = true;
    if (samples.size() == count) break;
    distances.for_each_within(next, std::numeric_limits<float>::infinity(),
                              [&](VertexId v, float d) { nearest[v] = std::min(nearest[v], d); });
    std::size_t best = vertex_count;
    for (std::size_t v = 0; v < vertex_count; ++v) {
      if (!taken[v] && (best == vertex_count || nearest[v] > nearest[best])) best = v;
    }
    next = VertexId(best);
  }
  return samples;
}

}  // namespace

std::vector<VertexId> place_particles(const DistanceStore& distances, const PlacementRequest& request) {
  const std::size_t vertex_count = distances.vertex_count();
  switch (request.init) {
    case Init::v0:
      return std::vector<VertexId>(request.particle_count, request.start_vertex.value_or(0));
    case Init::random:
      return distinct_random_vertices(vertex_count, request.particle_count, request.seed);
    case Init::farthest: {
      const VertexId first = request.start_vertex ? *request.start_vertex
                                                  : VertexId(SplitMix64(request.seed).below(vertex_count));
      return farthest_point_samples(distances, request.particle_count, first);
    }
  }
  return {};
}

}  // namespace meshparticles
