#pragma once
// The centre of a particle's cavity: the point of its region of the
// geodesic Voronoi diagram farthest, along the surface, from the particles
// around it. Farthest-point optimization moves a particle there (spread's
// evening, particles/local_farthest_points); taken away, a particle leaves
// its region to its neighbours, so the farthest point from them lies in it.
//
// Each particle around brings its ball (the vertices within a reach of it,
// with fast marching's distances). In a triangle whose three corners a
// ball reaches, that particle is a source laid in the triangle's plane
// (geodesics/planar_source), so a triangle's farthest point from all of
// them is plane geometry: the centre of the circle through three sources,
// a point of an edge two sources are equally near, or a corner. Straight
// lines in a tangent plane, used up to 0.24.0, misread a curved part's
// neighbours by several per cent, and the move most needed was never
// proposed (docs/ALGORITHM.md, "Evening").
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "geodesics/planar_source.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

// A particle's ball: vertices and their distances from it, in any order.
using ParticleBall = std::vector<std::pair<VertexId, float>>;

struct CavityCentre {
  SurfaceLocation at;                                        // the farthest point found
  double away = -std::numeric_limits<double>::infinity();    // its distance from the nearest particle around
  double here = std::numeric_limits<double>::infinity();     // the same, from where the particle stands
};

// What cavity_centre keeps between calls (one per thread).
struct CavityScratch {
  std::vector<std::int32_t> row;  // per vertex of the mesh: its row of `table`, or -1
  std::vector<VertexId> vertices;  // by row
  std::vector<std::uint32_t> triangles, sources;
  std::vector<float> table;    // a column a source, a row a vertex: its distance (+inf: beyond its ball)
  std::vector<float> nearest;  // by row: the least of the sources' distances
  std::vector<double> ways;    // 3 a triangle: each corner's way to the farther other corner
  std::vector<PlanarSource> planar, near;
  std::vector<std::pair<double, std::uint32_t>> order;  // (bound, triangle)
};

struct Cavity {
  const SurfaceLocation& at;           // where the particle stands
  std::span<const VertexId> region;    // the vertices it owns
  std::span<const std::uint32_t> near;  // the particles whose regions touch its own
  // Particles further out: each counts only where its straight line (no
  // longer than its way along the surface) to some vertex of the region is
  // under the widest gap found without them.
  std::span<const std::uint32_t> further;
};

// The point of the triangles around `cavity.region`'s vertices (and the
// particle's own triangle) farthest from the particles listed, each through
// its ball in `balls` (a particle's distances beyond its ball: none, there
// others are nearer). Ties go to the point found first: the triangles are
// searched by decreasing bound, then index.
CavityCentre cavity_centre(const SurfaceMesh& mesh, const VertexTriangles& rings, const Cavity& cavity,
                           const std::vector<SurfaceLocation>& points, const std::vector<ParticleBall>& balls,
                           CavityScratch& scratch);

}  // namespace meshparticles
