#pragma once
// The mesh spread's particles move on (docs/ALGORITHM.md, "The
// resolution"): the input refined by midpoint rounds until it has
// `vertices_per_particle` vertices per particle, then with every edge still
// longer than kSpreadLongestEdge hexagonal spacings split where it is,
// within a cap on the vertices known before anything is built. One rule
// for the run and for `quality`, which measures a spread run's particles
// on the same mesh.
#include <cstddef>
#include <optional>
#include <string>

#include "mesh/midpoint_refinement.hpp"

namespace meshparticles {

// The default vertices per particle: the fewest that met the floors
// on the committed meshes; more spreads further (higher rho, lower CV) at a
// larger cover and cost. Measured: docs/ALGORITHM.md.
inline constexpr double kSpreadVerticesPerParticle = 24;
// Then no edge longer than this many hexagonal spacings (split where they
// are: on meshes that mix large and small triangles, the closest pairs sat
// in the large ones; the uniform rounds leave a regular mesh alone).
inline constexpr double kSpreadLongestEdge = 0.5;
// At most this many vertices (time grows with them: the 1M sphere at
// n = 100,000 takes 4M, 101 s against 31 s unrefined, for rho 0.78 against
// 0.69), or half the usable memory at this many bytes a vertex (measured
// peak of that run: 4.46 GB for 3,994,242 vertices). Only where memory sets
// the cap and the cap cuts the mesh short do a run's particles depend on the
// machine: the run says so on stderr and in report.json.
inline constexpr std::size_t kSpreadMaxWorkingVertices = 5'000'000;
inline constexpr double kSpreadBytesPerWorkingVertex = 1200;

struct WorkingMeshPlan {
  unsigned levels = 0;             // midpoint rounds everywhere
  double longest_edge = 0;         // then split edges longer than this (mesh units)
  std::size_t max_vertices = 0;    // the cap, at least the input's vertices
  // What set the cap: empty for kSpreadMaxWorkingVertices (or the input's
  // size), else the memory that did (memory_guard's name for it).
  std::string cap_set_by_memory;
  // Fewer vertices than the particles asked for: the next round would pass the cap.
  bool capped = false;
};

WorkingMeshPlan plan_working_mesh(const SurfaceMesh& input, std::size_t particles, double vertices_per_particle);

// Where spread's relaxation is not kept, its sweeps go on on the working
// mesh cut this many midpoint rounds more (each about four times the
// vertices): a finer mesh lets farthest-point optimization spread further
// (docs/ALGORITHM.md, "Finer sweeps"). None where that passes the cap.
inline constexpr unsigned kFinerSweepsRounds = 1;
std::optional<WorkingMeshPlan> plan_finer_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan);
RefinedMesh build_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan);

}  // namespace meshparticles
