#include "options/run_option_values.hpp"

#include "geodesics/geodesic_solver.hpp"
#include "options/distance_requests.hpp"
#include "particles/particle_params.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

GeodesicsRequest geodesics_request(const RunOptionValues& given) {
  const GeodesicsRequest defaults;
  return geodesics_request(given.geodesic ? parse_method(*given.geodesic) : defaults.method,
                           given.threads ? unsigned(*given.threads) : defaults.threads, given.quiet, given.no_cache,
                           given.cache_dir);
}

DistancesRequest distances_request(const RunOptionValues& given, const GeodesicsRequest& geodesics) {
  const StoreKind store = given.distances ? parse_store_kind(*given.distances) : DistancesRequest().kind;
  return {geodesics, store, given.cutoff};
}

RunRequest run_request(const RunOptionValues& given) {
  RunRequest request;
  if (given.particles) request.particles = *given.particles;
  if (given.method) request.method = parse_method_option(*given.method);
  request.vertices_per_particle = given.vertices_per_particle;
  request.relax_rounds = given.relax_rounds;
  if (given.iterations) request.max_iterations = *given.iterations;
  if (given.backend) request.backend.name = *given.backend;
  if (given.scheme) request.scheme = parse_scheme(*given.scheme);
  if (given.colors) request.colors = unsigned(*given.colors);
  if (given.init) request.init = parse_init(*given.init);
  request.start_vertex = given.start_vertex;
  if (given.seed) request.seed = *given.seed;
  request.sigma = given.sigma;
  if (given.potential) request.potential = parse_potential(*given.potential);
  request.distances = distances_request(given, geodesics_request(given));
  request.geodesic_given = given.geodesic.has_value();  // else the paper method's default may give a GPU the balls
  if (given.device) request.backend.device = *given.device;
  request.distances.geodesics.device = request.backend.device;
  request.backend.work_group_size = given.wg;
  request.backend.tile_size = given.tile;
  if (given.weights) request.backend.weights = parse_weight_format(*given.weights);
  request.backend.rebuild_every = given.rebuild_every;
  request.backend.tuning_file = tuning_file_or_default(given.tuning_file ? given.tuning_file->string() : "");
  request.quiet = given.quiet;
  return request;
}

MeshReadOptions mesh_read_options(const RunOptionValues& given) {
  MeshReadOptions read;
  read.strict = given.strict;
  return read;
}

}  // namespace meshparticles
