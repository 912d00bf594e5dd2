#pragma once
// The options of a run as given, before any default: the command line
// (cli/run_options.cpp) and the Python keywords (python/run_settings.cpp)
// each fill one through the rows of options/run_option_table, then both turn it
// into a RunRequest by the same function, so that every default is
// RunRequest's and every word is read one way.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "mesh/mesh_checks.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// A whole number within its row's range, a finite number above 0, a word
// (among its row's words on the command line), a path; absent: not given.
// A flag is false unless given.
struct RunOptionValues {
  std::optional<std::uint64_t> particles;
  std::optional<std::string> method;
  std::optional<double> vertices_per_particle;
  std::optional<std::uint64_t> relax_rounds;
  std::optional<std::uint64_t> iterations;
  std::optional<std::string> backend;
  std::optional<std::string> scheme;
  std::optional<std::uint64_t> colors;
  std::optional<std::string> init;
  std::optional<std::uint64_t> start_vertex;
  std::optional<std::uint64_t> seed;
  std::optional<double> sigma;
  std::optional<std::string> potential;
  std::optional<std::string> geodesic;
  std::optional<std::string> distances;
  std::optional<double> cutoff;
  std::optional<std::string> device;
  std::optional<std::uint64_t> wg;
  std::optional<std::uint64_t> tile;
  std::optional<std::string> weights;
  std::optional<std::uint64_t> rebuild_every;
  std::optional<std::filesystem::path> tuning_file;
  bool strict = false;  // the mesh's reading (MeshReadOptions), not the request's
  std::optional<std::filesystem::path> cache_dir;
  bool no_cache = false;
  std::optional<std::uint64_t> threads;
  bool quiet = false;
};

// The solver, cache, threads and quiet (geodesic, cache-dir, no-cache,
// threads, quiet): the defaults of GeodesicsRequest, the cache's default
// directory when none is named.
GeodesicsRequest geodesics_request(const RunOptionValues& given);

// The store and cutoff (distances, cutoff) over `geodesics`.
DistancesRequest distances_request(const RunOptionValues& given, const GeodesicsRequest& geodesics);

// The request, RunRequest's default for each option not given. Throws
// UserError for a word it does not know (the command line has refused
// those already, by its row's words). What options given together cannot
// do is refused by plan_run, for every caller.
RunRequest run_request(const RunOptionValues& given);

// How the mesh is read (strict).
MeshReadOptions mesh_read_options(const RunOptionValues& given);

}  // namespace meshparticles
