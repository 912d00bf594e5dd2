#include "run_settings.hpp"

#include <iostream>

#include "common/user_error.hpp"
#include "geodesics/distance_cache.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles::python {

GeodesicsRequest take_geodesics_request(KeywordOptions& options) {
  GeodesicsRequest request;
  request.method = parse_method(options.take_word("geodesic").value_or("fmm"));
  request.threads = unsigned(options.take_whole("threads", kThreadRange).value_or(0));
  request.quiet = options.take_flag("quiet").value_or(false);
  const auto cache_dir = options.take_path("cache_dir");
  if (options.take_flag("no_cache").value_or(false)) return request;
  if (cache_dir) {
    request.cache_directory = *cache_dir;
    return request;
  }
  try {
    request.cache_directory = default_cache_directory();
  } catch (const UserError& problem) {  // the cache only saves time: go on without it, as the command line does
    if (!request.quiet) std::cerr << "meshparticles: warning: " << problem.what() << "; not cached\n";
  }
  return request;
}

DistancesRequest take_distances_request(KeywordOptions& options, const GeodesicsRequest& geodesics) {
  DistancesRequest request;
  request.geodesics = geodesics;
  request.kind = parse_store_kind(options.take_word("distances").value_or("auto"));
  if (const auto cutoff = options.take_positive("cutoff")) {
    if (request.kind == StoreKind::dense) throw UserError("cutoff applies to distances local and auto");
    request.cutoff = *cutoff;
  }
  return request;
}

RunRequest take_run_request(KeywordOptions& options) {
  RunRequest request;
  if (const auto method = options.take_word("method")) request.method = parse_method_option(*method);
  request.vertices_per_particle = options.take_positive("vertices_per_particle");
  if (const auto rounds = options.take_whole("relax_rounds", kRelaxRoundRange)) request.relax_rounds = *rounds;
  request.max_iterations = options.take_whole("iterations", kRunIterationRange).value_or(kDefaultMaxIterations);
  request.backend.name = options.take_word("backend").value_or("");  // empty: the default rule of plan_run
  if (const auto scheme = options.take_word("scheme")) request.scheme = parse_scheme(*scheme);
  if (const auto colors = options.take_whole("colors", kColorRange)) request.colors = unsigned(*colors);
  request.init = parse_init(options.take_word("init").value_or("farthest"));
  request.start_vertex = options.take_whole("start_vertex", kVertexIdRange);
  request.seed = options.take_whole("seed", kSeedRange).value_or(1);
  request.potential = parse_potential(options.take_word("potential").value_or("exp"));
  request.sigma = options.take_positive("sigma");
  request.backend.device = options.take_word("device").value_or("");
  request.backend.work_group_size = options.take_whole("wg", kWorkGroupRange);
  request.backend.tile_size = options.take_whole("tile", kTileRange);
  if (const auto weights = options.take_word("weights")) request.backend.weights = parse_weight_format(*weights);
  request.backend.rebuild_every = options.take_whole("rebuild_every", kRebuildRange);
  request.backend.tuning_file = tuning_file_or_default(options.take_path("tuning_file").value_or("").string());
  request.geodesic_given = options.given("geodesic");  // else the default may give a GPU the balls, as `run`'s
  const GeodesicsRequest geodesics = take_geodesics_request(options);
  request.distances = take_distances_request(options, geodesics);
  request.quiet = geodesics.quiet;
  return request;
}

}  // namespace meshparticles::python
