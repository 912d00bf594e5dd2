#pragma once
// The geodesics request, built once for both front ends: the command line
// (cli/geodesics_options.cpp, options/run_option_values.cpp) and the Python
// keywords (python/run_settings.cpp, python/quality_binding.cpp).
#include <filesystem>
#include <optional>

#include "geodesics/distance_cache.hpp"

namespace meshparticles {

// The cache: none with `no_cache`, else `cache_dir`, else the default one
// (when there is none, a warning unless `quiet`, and no cache: it only saves time).
GeodesicsRequest geodesics_request(GeodesicMethod method, unsigned threads, bool quiet, bool no_cache,
                                   const std::optional<std::filesystem::path>& cache_dir);

}  // namespace meshparticles
