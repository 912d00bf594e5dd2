#include <iostream>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

GeodesicsRequest DistanceTableOptions::request(GeodesicMethod method) const {
  GeodesicsRequest request;
  request.method = method;
  request.threads = threads;
  request.quiet = quiet;
  if (no_cache) return request;
  if (!cache_dir.empty()) {
    request.cache_directory = std::filesystem::path(cache_dir);
    return request;
  }
  try {
    request.cache_directory = default_cache_directory();
  } catch (const UserError& problem) {  // the cache only saves time: go on without it
    if (!quiet) std::cerr << "meshparticles: warning: " << problem.what() << "; not cached\n";
  }
  return request;
}

void add_distance_table_options(CLI::App& command, DistanceTableOptions& options) {
  command.add_option("--cache-dir", options.cache_dir, "Distance cache directory (default: $XDG_CACHE_HOME/meshparticles)");
  command.add_flag("--no-cache", options.no_cache, "Neither read nor write the distance cache");
  add_whole_number_option(command, "--threads", options.threads, kThreadRange,
                          "Threads for all-pairs distances (0: all cores)");
  command.add_flag("-q,--quiet", options.quiet, "No progress or warnings on stderr");
}

}  // namespace meshparticles
