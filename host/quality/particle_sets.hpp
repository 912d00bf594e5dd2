#pragma once
// Particle files measured on a mesh, for `quality` (one set) and `compare`
// (two side by side, plus how far each set's particles are from the other's).
#include <optional>
#include <string>
#include <vector>

#include "mesh/midpoint_refinement.hpp"
#include "particles/particle_file.hpp"
#include "quality/distribution_quality.hpp"

namespace meshparticles {

struct MeasuredSet {
  std::string path;
  SnappedParticles snapped;
  EnergyParams energy;  // sigma: --sigma, else the default rule for this set's n
  DistributionQuality quality;
};

// The mesh particle files are measured on: `uniform_levels` given, that
// many midpoint rounds everywhere; `spread`, the working mesh a default
// spread run of the smallest set's n takes; neither (auto), the mesh
// itself where every point of every set lies on its vertices (within
// kOnVertex hexagonal spacings: a paper run's, a vertex sampler's), else
// that working mesh. Points that are not on its vertices are then inserted
// as vertices (place_on_vertices): measured where they are, not snapped.
inline constexpr double kOnVertex = 0.005;
struct MeasuringMesh {
  RefinedMesh refined;
  bool spread = false;  // the spread working mesh, else uniform rounds
};
MeasuringMesh measuring_mesh(const SurfaceMesh& mesh, const std::vector<std::vector<Vec3>>& sets,
                             std::optional<unsigned> uniform_levels, bool spread);

// Each point of each set as a vertex of `measuring`: the vertex it is on
// (within kOnVertexExactly mean edges), else the nearest surface point,
// inserted into `measuring` as a vertex. largest_snap: the largest distance
// from a point to its vertex, that is to the surface (insertion moves a
// point onto an edge or corner within 2% of a triangle's height of it).
inline constexpr double kOnVertexExactly = 1e-9;
std::vector<SnappedParticles> place_on_vertices(RefinedMesh& measuring, const SurfaceMesh& input,
                                                const std::vector<std::vector<Vec3>>& sets);

// `placed`: one set of place_on_vertices on `mesh`.
MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceStore& distances, GeodesicMethod method,
                                  const std::string& path, SnappedParticles placed, Potential potential,
                                  std::optional<double> sigma, bool quiet);

// The mean over the particles of `from` of the geodesic distance to the
// nearest particle of `to` (+inf when some particle has none in its
// component), by one solve from all of `to`.
double mean_distance_to_nearest(const SurfaceMesh& mesh, GeodesicMethod method, const std::vector<VertexId>& from,
                                const std::vector<VertexId>& to);

}  // namespace meshparticles
