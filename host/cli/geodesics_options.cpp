#include "cli/commands.hpp"
#include "cli/distance_requests.hpp"
#include "cli/number_options.hpp"
#include "cli/run_option_table.hpp"
#include "common/text_format.hpp"
#include "particles/potentials.hpp"

namespace meshparticles {

GeodesicsRequest DistanceTableOptions::request(GeodesicMethod method) const {
  return geodesics_request(method, threads, quiet, no_cache,
                           cache_dir.empty() ? std::nullopt : std::optional(std::filesystem::path(cache_dir)));
}

void add_geodesic_option(CLI::App& command, std::string& method, const std::string& default_note) {
  command
      .add_option("--geodesic", method,
                  "Distance solver: fmm (fast marching), fim (the fast iterative method) or dijkstra (edge graph)" +
                      (default_note.empty() ? "" : "; " + default_note))
      ->check(CLI::IsMember(run_option("geodesic").words))
      ->capture_default_str();
}

void add_potential_option(CLI::App& command, std::string& potential) {
  std::string help;
  for (const PotentialSpec& spec : potential_table()) {
    help += (help.empty() ? "" : "; ") + spec.name + ": " + spec.weight;
  }
  command.add_option("--potential", potential, help)
      ->check(CLI::IsMember(run_option("potential").words))
      ->capture_default_str();
}

void add_distance_table_options(CLI::App& command, DistanceTableOptions& options) {
  command.add_option("--cache-dir", options.cache_dir, "Distance cache directory (default: $XDG_CACHE_HOME/meshparticles)");
  command.add_flag("--no-cache", options.no_cache, "Neither read nor write the distance cache");
  add_whole_number_option(command, "--threads", options.threads, run_option("threads").range,
                          "Threads for all-pairs distances (0: all cores)");
  command.add_flag("-q,--quiet", options.quiet, "No progress or warnings on stderr");
}

DistancesRequest DistanceStoreOptions::request(const GeodesicsRequest& geodesics) const {
  return distances_request(geodesics, parse_store_kind(store), cutoff, OptionSpelling::command_line);
}

void add_distance_store_options(CLI::App& command, DistanceStoreOptions& options) {
  command
      .add_option("--distances", options.store,
                  "dense (the V x V table, cached on disk), local (each vertex's ball within --cutoff, computed on "
                  "demand) or auto (dense up to " + std::to_string(kAutoDenseVertices) +
                  " vertices, when cached, or when the backend needs it; else local)")
      ->check(CLI::IsMember(run_option("distances").words))
      ->capture_default_str();
  add_positive_number_option(command, "--cutoff", options.cutoff,
                             "Local distances: the balls' radius in hexagonal spacings d_hex (default " +
                                 format_number("%g", kDefaultCutoff) + ")");
}

}  // namespace meshparticles
