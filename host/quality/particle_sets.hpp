#pragma once
// Particle files measured on a mesh, for `quality` (one set) and `compare`
// (two side by side, plus how far each set's particles are from the other's).
#include <optional>
#include <string>
#include <vector>

#include "particles/particle_file.hpp"
#include "quality/distribution_quality.hpp"

namespace meshparticles {

struct MeasuredSet {
  std::string path;
  SnappedParticles snapped;
  EnergyParams energy;  // sigma: --sigma, else the default rule for this set's n
  DistributionQuality quality;
};

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
