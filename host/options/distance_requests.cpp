#include "options/distance_requests.hpp"

#include <iostream>

#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"

namespace meshparticles {

GeodesicsRequest geodesics_request(GeodesicMethod method, unsigned threads, bool quiet, bool no_cache,
                                   const std::optional<std::filesystem::path>& cache_dir) {
  GeodesicsRequest request;
  request.method = method;
  request.threads = threads;
  request.quiet = quiet;
  if (no_cache) return request;
  if (cache_dir) {
    request.cache_directory = *cache_dir;
    return request;
  }
  try {
    request.cache_directory = default_cache_directory();
  } catch (const UserError& problem) {  // the cache only saves time: go on without it
    if (!quiet) std::cerr << "meshparticles: warning: " << problem.what() << "; not cached\n";
  }
  return request;
}

}  // namespace meshparticles
