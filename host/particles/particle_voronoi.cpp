#include "particles/particle_voronoi.hpp"

#include <limits>

namespace meshparticles {

namespace {
constexpr VertexId kAbsent = 0xFFFFFFFFu;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
}  // namespace

ParticleVoronoi::ParticleVoronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::size_t particle_count)
    : mesh_(mesh),
      solver_(solver),
      nearest_(mesh.vertex_count(), kInfinity),
      owner_(mesh.vertex_count(), kNoParticle),
      vertex_(particle_count, kAbsent),
      region_size_(particle_count, 0),
      visited_(mesh.vertex_count(), 0),
      farthest_(nearest_) {}

std::optional<VertexId> ParticleVoronoi::vertex_of(std::uint32_t particle) const {
  if (vertex_[particle] == kAbsent) return std::nullopt;
  return vertex_[particle];
}

void ParticleVoronoi::assign(std::span<const VertexId> vertices, std::span<const std::uint32_t> owners) {
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const VertexId v = vertices[k];
    if (owner_[v] != kNoParticle) {
      --region_size_[owner_[v]];
      reshaped_.push_back(owner_[v]);
    }
    owner_[v] = owners[k];
    ++region_size_[owners[k]];
    reshaped_.push_back(owners[k]);
  }
}

void ParticleVoronoi::insert(std::uint32_t particle, VertexId v) {
  reshaped_.clear();
  vertex_[particle] = v;
  solver_.lower_nearest(v, nearest_, scratch_, lowered_);
  lowered_owners_.assign(lowered_.size(), particle);
  assign(lowered_, lowered_owners_);
  farthest_.take(v);
  farthest_.lowered(lowered_);
}

// The vertices `particle` owns: a walk over its region from its vertex,
// which holds them all unless another particle's march cut the region in
// two (possible where fast marching's one-sided distances nearly tie); then
// a scan of every vertex finds the rest.
std::vector<VertexId> ParticleVoronoi::region_of(std::uint32_t particle, VertexId at) {
  std::vector<VertexId> region;
  region.reserve(region_size_[particle]);
  if (owner_[at] == particle) {
    region.push_back(at);
    visited_[at] = 1;
  }
  for (std::size_t next = 0; next < region.size(); ++next) {
    for (const VertexId u : mesh_.one_ring(region[next])) {
      if (visited_[u] || owner_[u] != particle) continue;
      visited_[u] = 1;
      region.push_back(u);
    }
  }
  if (region.size() != region_size_[particle]) {
    for (VertexId v = 0; v < mesh_.vertex_count(); ++v) {
      if (owner_[v] == particle && !visited_[v]) region.push_back(v);
    }
  }
  for (const VertexId v : region) visited_[v] = 0;
  return region;
}

void ParticleVoronoi::remove(std::uint32_t particle) {
  reshaped_.clear();
  const VertexId at = vertex_[particle];
  const std::vector<VertexId> region = region_of(particle, at);
  for (const VertexId v : region) {
    nearest_[v] = kInfinity;
    owner_[v] = kNoParticle;
    visited_[v] = 1;  // in the region: not part of its rim
  }
  region_size_[particle] = 0;
  vertex_[particle] = kAbsent;
  // The rim: the vertices just outside the region, each starting from the
  // distance it has to its own particle.
  rim_.clear();
  rim_owners_.clear();
  for (const VertexId v : region) {
    for (const VertexId u : mesh_.one_ring(v)) {
      if (visited_[u] || owner_[u] == kNoParticle) continue;
      visited_[u] = 1;
      rim_.push_back(u);
      rim_owners_.push_back(owner_[u]);
    }
  }
  for (const VertexId v : region) visited_[v] = 0;
  for (const VertexId u : rim_) visited_[u] = 0;
  if (!rim_.empty()) {
    solver_.lower_nearest_from(rim_, rim_owners_, nearest_, scratch_, lowered_, lowered_owners_);
    assign(lowered_, lowered_owners_);
  } else {
    lowered_.clear();
  }
  farthest_.release(at);
  farthest_.changed(region);
  farthest_.lowered(lowered_);
}

}  // namespace meshparticles
