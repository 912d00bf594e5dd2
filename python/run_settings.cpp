#include "run_settings.hpp"

#include "cli/distance_requests.hpp"
#include "cli/run_option_table.hpp"
#include "particles/potentials.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles::python {

GeodesicsRequest take_geodesics_request(KeywordOptions& options) {
  const GeodesicMethod method = parse_method(options.take_word("geodesic").value_or("fmm"));
  const auto threads = unsigned(options.take_whole("threads", run_option("threads").range).value_or(0));
  const bool quiet = options.take_flag("quiet").value_or(false);
  const auto cache_dir = options.take_path("cache_dir");
  const bool no_cache = options.take_flag("no_cache").value_or(false);
  return geodesics_request(method, threads, quiet, no_cache, cache_dir);
}

DistancesRequest take_distances_request(KeywordOptions& options, const GeodesicsRequest& geodesics) {
  const StoreKind store = parse_store_kind(options.take_word("distances").value_or("auto"));
  return distances_request(geodesics, store, options.take_positive("cutoff"), OptionSpelling::python);
}

RunRequest take_run_request(KeywordOptions& options) {
  RunRequest request;
  if (const auto method = options.take_word("method")) request.method = parse_method_option(*method);
  request.vertices_per_particle = options.take_positive("vertices_per_particle");
  if (const auto rounds = options.take_whole("relax_rounds", run_option("relax-rounds").range)) request.relax_rounds = *rounds;
  request.max_iterations = options.take_whole("iterations", run_option("iterations").range).value_or(kDefaultMaxIterations);
  request.backend.name = options.take_word("backend").value_or("");  // empty: the default rule of plan_run
  if (const auto scheme = options.take_word("scheme")) request.scheme = parse_scheme(*scheme);
  if (const auto colors = options.take_whole("colors", run_option("colors").range)) request.colors = unsigned(*colors);
  request.init = parse_init(options.take_word("init").value_or("farthest"));
  request.start_vertex = options.take_whole("start_vertex", run_option("start-vertex").range);
  request.seed = options.take_whole("seed", run_option("seed").range).value_or(1);
  request.potential = parse_potential(options.take_word("potential").value_or(potential_name(kDefaultPotential)));
  request.sigma = options.take_positive("sigma");
  request.backend.device = options.take_word("device").value_or("");
  request.backend.work_group_size = options.take_whole("wg", run_option("wg").range);
  request.backend.tile_size = options.take_whole("tile", run_option("tile").range);
  if (const auto weights = options.take_word("weights")) request.backend.weights = parse_weight_format(*weights);
  request.backend.rebuild_every = options.take_whole("rebuild_every", run_option("rebuild-every").range);
  request.backend.tuning_file = tuning_file_or_default(options.take_path("tuning_file").value_or("").string());
  request.geodesic_given = options.given("geodesic");  // else the default may give a GPU the balls, as `run`'s
  const GeodesicsRequest geodesics = take_geodesics_request(options);
  request.distances = take_distances_request(options, geodesics);
  request.quiet = geodesics.quiet;
  return request;
}

}  // namespace meshparticles::python
