#pragma once
// One shape's result of correspond (population_correspondence): where its
// particles lie, how it was aligned, and how evenly they cover it. Types
// alone, so that shape_records (which encodes them) and the population's
// code need not include each other.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/surface_location.hpp"
#include "quality/distribution_quality.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

struct ShapeCorrespondence {
  std::filesystem::path mesh;
  std::size_t vertices = 0;
  MeshAlignment alignment;
  MeshTopology topology;                 // components, boundary loops, genus
  std::size_t repaired = 0;              // particles the transfer left out of place, put back (geodesic_repair)
  std::vector<InputLocation> locations;  // per particle: where it lies on this shape
  PointSet particles;                      // their positions, the shape's own coordinates
  DistributionQuality quality;             // how evenly they cover the shape, as `run` measures its own
};

}  // namespace meshparticles
