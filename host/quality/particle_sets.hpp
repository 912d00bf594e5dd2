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

// Points between vertices (a spread run's, or another tool's on the
// surface) are measured on a refined mesh where they lie on vertices or
// close to them (within kOnVertex hexagonal spacings: a nearest-neighbour
// distance then moves by at most twice that by snapping). `uniform_levels`
// given: that many midpoint rounds everywhere. `spread`: the working mesh a
// default spread run of the smallest set's n takes. Neither (auto): the
// mesh itself if every point of every set lies on its vertices, else that
// working mesh if they lie on it, else the fewest uniform rounds at which
// every point does, stopping short of
// kMeasuringVerticesPerParticle vertices per particle of the smallest set
// (and of kMeasuringMaxVertices). Round 0 is the mesh itself.
inline constexpr double kOnVertex = 0.005;
inline constexpr double kMeasuringVerticesPerParticle = 100;
inline constexpr std::size_t kMeasuringMaxVertices = 2'000'000;
struct MeasuringMesh {
  RefinedMesh refined;
  bool spread = false;  // the spread working mesh, else uniform rounds
};
MeasuringMesh measuring_mesh(const SurfaceMesh& mesh, const std::vector<std::vector<Vec3>>& sets,
                             std::optional<unsigned> uniform_levels, bool spread);

// `points`: read_particle_points(path), read by the caller before the
// distances so that a bad file fails fast.
MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceStore& distances, GeodesicMethod method,
                                  const std::string& path, const std::vector<Vec3>& points, Potential potential,
                                  std::optional<double> sigma, bool quiet);

// The mean over the particles of `from` of the geodesic distance to the
// nearest particle of `to` (+inf when some particle has none in its
// component), by one solve from all of `to`.
double mean_distance_to_nearest(const SurfaceMesh& mesh, GeodesicMethod method, const std::vector<VertexId>& from,
                                const std::vector<VertexId>& to);

}  // namespace meshparticles
