#pragma once
// The geodesics and distance-store requests, built and checked once for both
// front ends: the command line (cli/geodesics_options.cpp) and the Python
// keywords (python/run_settings.cpp). A refusal names the options as the
// front end spells them: "--cutoff applies to --distances local and auto"
// on the command line, "cutoff applies to distances local and auto" in
// Python.
#include <filesystem>
#include <optional>
#include <string>

#include "pipeline/distances.hpp"

namespace meshparticles {

enum class OptionSpelling { command_line, python };

// "--cache-dir" or "cache_dir" for the command line's name "cache-dir".
std::string spelled_option(const std::string& name, OptionSpelling spelling);

// The cache: none with `no_cache`, else `cache_dir`, else the default one
// (when there is none, a warning unless `quiet`, and no cache: it only saves time).
GeodesicsRequest geodesics_request(GeodesicMethod method, unsigned threads, bool quiet, bool no_cache,
                                   const std::optional<std::filesystem::path>& cache_dir);

// The store and the cutoff, if given: refused with the dense store.
DistancesRequest distances_request(const GeodesicsRequest& geodesics, StoreKind store,
                                   std::optional<double> cutoff, OptionSpelling spelling);

}  // namespace meshparticles
