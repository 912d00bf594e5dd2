#include "cli/commands.hpp"

namespace meshparticles {

GeodesicsRequest DistanceTableOptions::request(GeodesicMethod method) const {
  GeodesicsRequest request;
  request.method = method;
  request.threads = threads;
  request.quiet = quiet;
  if (!no_cache) request.cache_directory = cache_dir.empty() ? default_cache_directory() : std::filesystem::path(cache_dir);
  return request;
}

void add_distance_table_options(CLI::App& command, DistanceTableOptions& options) {
  command.add_option("--cache-dir", options.cache_dir, "Distance cache directory (default: $XDG_CACHE_HOME/meshparticles)");
  command.add_flag("--no-cache", options.no_cache, "Neither read nor write the distance cache");
  command.add_option("--threads", options.threads, "Threads for all-pairs distances (0: all cores)")
      ->check(CLI::Range(0u, 1024u));
  command.add_flag("-q,--quiet", options.quiet, "No progress or warnings on stderr");
}

}  // namespace meshparticles
