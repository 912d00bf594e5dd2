#pragma once
// The geodesic Voronoi diagram of particles on the vertices of a mesh, kept
// as particles come and go: each vertex's distance to its nearest particle
// and which particle that is, and the vertex farthest from all of them.
// What farthest-point optimization asks at every step.
//
// The distances are fast marching's, one-sided: a particle's region is
// marched from it when it arrives (stopping where another particle is no
// farther), and refilled from the regions around it when it leaves. Both
// cost in proportion to the region, about V / n vertices, not to the mesh.
// The distance at a vertex depends on the order particles came and went (a
// march stopped at a region's edge is not the unstopped march): the same
// sequence of calls gives the same bits, and every value is within the
// solver's accuracy of the distance to the nearest particle (tested).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/farthest_vertex.hpp"

namespace meshparticles {

class ParticleVoronoi {
 public:
  static constexpr std::uint32_t kNoParticle = 0xFFFFFFFFu;

  // An empty diagram for particles 0..particle_count-1 on `mesh`, measured
  // by `solver` (both outlive it).
  ParticleVoronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::size_t particle_count);

  // Puts an absent particle on vertex v (v must not hold another particle).
  void insert(std::uint32_t particle, VertexId v);
  // Takes a present particle away; its region goes to the particles around it.
  void remove(std::uint32_t particle);

  std::optional<VertexId> vertex_of(std::uint32_t particle) const;
  // The distance from v to its nearest particle (+inf in a component with none).
  float distance(VertexId v) const { return nearest_[v]; }
  std::span<const float> distances() const { return nearest_; }
  std::uint32_t owner(VertexId v) const { return owner_[v]; }  // kNoParticle where distance is +inf
  // The vertex farthest from every particle (ties: the smaller id); none
  // when every vertex holds a particle.
  std::optional<VertexId> farthest() const { return farthest_.farthest(); }
  // The vertices a present particle owns, its vertex first.
  std::vector<VertexId> region(std::uint32_t particle) { return region_of(particle, vertex_[particle]); }
  // The particles whose regions the last insert or remove changed (gained
  // or lost vertices), with repeats.
  std::span<const std::uint32_t> reshaped() const { return reshaped_; }

 private:
  std::vector<VertexId> region_of(std::uint32_t particle, VertexId at);
  void assign(std::span<const VertexId> vertices, std::span<const std::uint32_t> owners);

  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  std::vector<float> nearest_;
  std::vector<std::uint32_t> owner_;
  std::vector<VertexId> vertex_;               // per particle; kAbsent when not placed
  std::vector<std::uint32_t> region_size_;     // per particle: the vertices it owns
  std::vector<std::uint8_t> visited_;          // per vertex, clean between calls
  FarthestVertex farthest_;
  SolverScratch scratch_;
  std::vector<VertexId> lowered_, rim_;
  std::vector<std::uint32_t> lowered_owners_, rim_owners_, reshaped_;
};

}  // namespace meshparticles
