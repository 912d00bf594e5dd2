#include "cli/commands.hpp"
#include "options/distance_requests.hpp"
#include "options/number_options.hpp"
#include "options/run_option_table.hpp"

namespace meshparticles {

GeodesicsRequest DistanceTableOptions::request(GeodesicMethod method) const {
  return geodesics_request(method, threads, quiet, no_cache,
                           cache_dir.empty() ? std::nullopt : std::optional(std::filesystem::path(cache_dir)));
}

void add_geodesic_option(CLI::App& command, std::string& method, const std::string& default_note) {
  command
      .add_option("--geodesic", method,
                  geodesic_solver_help() + (default_note.empty() ? "" : "; " + default_note))
      ->check(CLI::IsMember(run_option("geodesic").words))
      ->capture_default_str();
}

void add_potential_option(CLI::App& command, std::string& potential) {
  command.add_option("--potential", potential, run_option("potential").help)
      ->check(CLI::IsMember(run_option("potential").words))
      ->capture_default_str();
}

void add_distance_table_options(CLI::App& command, DistanceTableOptions& options) {
  command.add_option("--cache-dir", options.cache_dir, run_option("cache-dir").help);
  command.add_flag("--no-cache", options.no_cache, run_option("no-cache").help);
  add_whole_number_option(command, "--threads", options.threads, run_option("threads").range, run_option("threads").help);
  command.add_flag(run_option("quiet").command_line_names(), options.quiet, run_option("quiet").help);
}

DistancesRequest DistanceStoreOptions::request(const GeodesicsRequest& geodesics) const {
  return {geodesics, parse_store_kind(store), cutoff};
}

void add_distance_store_options(CLI::App& command, DistanceStoreOptions& options) {
  command
      .add_option("--distances", options.store, run_option("distances").help)
      ->check(CLI::IsMember(run_option("distances").words))
      ->capture_default_str();
  add_positive_number_option(command, "--cutoff", options.cutoff, run_option("cutoff").help);
}

}  // namespace meshparticles
