#pragma once
// The mesh spread's particles move on (docs/ALGORITHM.md, "The
// resolution"): the input with every edge longer than `longest_edge`
// hexagonal spacings (kSpreadLongestEdge unless asked) split where it is
// (after midpoint rounds to `vertices_per_particle` vertices per particle
// where that is asked for),
// within a cap on the vertices known before anything is built. One rule
// for the run and for `quality`, which measures a spread run's particles
// on the same mesh.
#include <cstddef>
#include <optional>
#include <string>

#include "mesh/midpoint_refinement.hpp"

namespace meshparticles {

// The default vertices per particle of the midpoint rounds: none. Rounds
// over the whole input multiply its vertices by about 4 each and overshoot
// where the input is fine already (homer at 1,024: 79 a particle for 24
// asked); the long edges alone give 26 to 39 a particle on the CGAL models
// at 1,024 and 4,096, at 0.7 to 0.97 of the time and a little more even.
// Measured: docs/ALGORITHM.md, "The resolution". --vertices-per-particle
// asks for rounds.
inline constexpr double kSpreadVerticesPerParticle = 0;
// No edge longer than this many hexagonal spacings, split where it is, round
// after round: the resolution the sweeps move at, on the triangles that need
// it (the committed meshes get 25 to 28 vertices a particle at 1,024; a mix
// of large and small triangles more where they are large). 0.35 cost less
// but fell short of the rounds' evenness at 256 and on some models.
inline constexpr double kSpreadLongestEdge = 0.3;
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

// `longest_edge` in hexagonal spacings at `particles`.
WorkingMeshPlan plan_working_mesh(const SurfaceMesh& input, std::size_t particles, double vertices_per_particle,
                                  double longest_edge);

// Where spread's relaxation is not kept, its sweeps go on on the working
// mesh cut this many midpoint rounds more (each about four times the
// vertices): a finer mesh lets farthest-point optimization spread further
// (docs/ALGORITHM.md, "Finer sweeps"). None where that passes the cap.
inline constexpr unsigned kFinerSweepsRounds = 1;
std::optional<WorkingMeshPlan> plan_finer_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan);
RefinedMesh build_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan);

}  // namespace meshparticles
