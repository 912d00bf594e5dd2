#pragma once
// The pipeline's distance step: the store every later step reads, from the
// disk cache when it holds this mesh's table, else computed (and cached).
#include <memory>

#include "geodesics/distance_cache.hpp"
#include "geodesics/distance_store.hpp"

namespace meshparticles {

struct ObtainedDistances {
  std::unique_ptr<DistanceStore> store;
  std::string kind = "dense";  // the store's kind, for reports
  TableSource source;          // from the cache or computed, and the cache file
  double seconds = 0;          // wall time of this step
};

ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& request);

}  // namespace meshparticles
