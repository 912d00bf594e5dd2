#pragma once
// The centre of a particle's cavity: the point of its region of the
// geodesic Voronoi diagram farthest, along the surface, from the particles
// around it (kernels/cavity_centre.h, where the search is written once for
// the host and the device; docs/ALGORITHM.md, "Evening"). Here: the host's
// side of it, the surface and the balls laid out as that code reads them,
// its scratch, and the call.
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "cavity_centre.h"
#include "geodesics/planar_source.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

static_assert(sizeof(unsigned int) == sizeof(VertexId), "the shared code reads vertex ids as unsigned int");

// A march's ball, as the solver gives it: vertices and their distances.
using ParticleBall = std::vector<std::pair<VertexId, float>>;

// The surface as kernels/cavity_centre.h reads it: positions, corners and
// each vertex's fan, laid out once per mesh.
class CavitySurface {
 public:
  // `fans` must outlive this object.
  CavitySurface(const SurfaceMesh& mesh, const VertexTriangles& fans);
  cavity_surface view() const;
  const std::vector<vec3d>& positions() const { return positions_; }
  const std::vector<unsigned int>& corners() const { return corners_; }

 private:
  std::vector<vec3d> positions_;
  std::vector<unsigned int> corners_;  // 3 a triangle
  const VertexTriangles& fans_;
};

// Every particle's ball one after another, each in increasing vertex order;
// a particle's ball put in anew goes to the end (the space of its last
// one is taken back when the dead space outgrows the live).
class ParticleBalls {
 public:
  explicit ParticleBalls(std::size_t particles) : start_(particles, 0), size_(particles, 0) {}
  // Particle k's ball is `ball`, in increasing vertex order.
  void set(std::uint32_t k, const ParticleBall& ball);
  std::span<const ball_entry> operator[](std::uint32_t k) const { return {entries_.data() + start_[k], size_[k]}; }
  // The view of kernels/cavity_centre.h, with `points` where the particles stand.
  cavity_particles view(const std::vector<vec3d>& points) const;
  const std::vector<ball_entry>& entries() const { return entries_; }
  const std::vector<std::uint32_t>& starts() const { return start_; }
  const std::vector<std::uint32_t>& sizes() const { return size_; }
  // How many times the dead space was taken back (every entry moved).
  std::size_t compactions() const { return compactions_; }

 private:
  std::vector<ball_entry> entries_;
  std::vector<std::uint32_t> start_, size_;
  std::size_t live_ = 0;  // entries some particle's ball holds
  std::size_t compactions_ = 0;
};

struct CavityCentre {
  SurfaceLocation at;                                      // the farthest point found
  double away = -std::numeric_limits<double>::infinity();  // its distance from the nearest particle around
  double here = std::numeric_limits<double>::infinity();   // the same, from where the particle stands
};

// What cavity_centre works in (one per thread), grown to each call's sizes.
struct CavityScratch {
  std::vector<unsigned int> triangles, triangle_slots, vertex_slots, vertices, corner_rows, near;
  std::vector<double> bounds, ways;
  std::vector<float> nearest, table;
  std::vector<planar_source> planar;
  cavity_scratch fit(const cavity_scratch_size& size);
};

struct Cavity {
  const SurfaceLocation& at;            // where the particle stands
  std::span<const VertexId> region;     // the vertices it owns
  std::span<const std::uint32_t> near;  // the particles whose regions touch its own
  // Particles further out: each counts only where its straight line (no
  // longer than its way along the surface) to some vertex of the region is
  // under the widest gap found without them.
  std::span<const std::uint32_t> further;
};

// The shared code's cavity for `c`.
cavity cavity_of(const Cavity& c);

// The point of the triangles around `c.region`'s vertices (and the
// particle's own triangle) farthest from the particles listed, each through
// its ball in `balls`, the particles standing at `points`
// (kernels/cavity_centre.h's cavity_centre).
CavityCentre cavity_centre(const CavitySurface& surface, const Cavity& c, const std::vector<vec3d>& points,
                           const ParticleBalls& balls, CavityScratch& scratch);

// What the shared code found, as a point of the surface.
CavityCentre cavity_centre_found(const cavity_found& found);

}  // namespace meshparticles
