#pragma once
// `quality` and `compare` as a library call, for the command line and the
// Python module alike: one or two point sets measured on the same
// measuring mesh and distances, and, for two, how far each set's particles
// are from the other's.
#include <optional>
#include <string>
#include <vector>

#include "particles/potentials.hpp"
#include "pipeline/distances.hpp"
#include "quality/particle_sets.hpp"

namespace meshparticles {

struct PointSetsRequest {
  std::vector<std::string> names;             // each set's label in the report (its file, or "<points>")
  std::vector<std::vector<Vec3>> points;      // one set (quality) or two (compare)
  std::optional<unsigned> uniform_levels;     // --refine L
  bool spread_mesh = false;                   // --refine spread
  GeodesicsRequest geodesics;
  DistancesRequest distances;
  Potential potential = kDefaultPotential;
  std::optional<double> sigma;                // default: the run's rule for each set's n
};

struct PointSetsMeasurement {
  MeasuringMesh measuring;
  std::vector<MeasuredSet> sets;
  // Two sets: the mean distance from A's particles to the nearest of B's, and back.
  std::optional<double> mean_a_to_b, mean_b_to_a;
};

// `refine` as `--refine` takes it: auto, spread, or 0 to 8 uniform rounds,
// into the request's uniform_levels and spread_mesh. Throws UserError for
// anything else.
void set_refinement(PointSetsRequest& request, const std::string& refine);

// Throws UserError for a sigma too small to compute with, before the distances.
PointSetsMeasurement measure_point_sets(const SurfaceMesh& input, const PointSetsRequest& request);

}  // namespace meshparticles
