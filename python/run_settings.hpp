#pragma once
// The keyword options of run() and quality() turned into the pipeline's
// requests, by the command line's names and defaults (cli/run_options.cpp,
// cli/geodesics_options.cpp): `--rebuild-every` is rebuild_every=, and so on.
#include "keyword_options.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles::python {

// geodesic=, cache_dir=, no_cache=, threads=, quiet=.
GeodesicsRequest take_geodesics_request(KeywordOptions& options);

// distances=, cutoff=, over the geodesics request.
DistancesRequest take_distances_request(KeywordOptions& options, const GeodesicsRequest& geodesics);

// Every option of `meshparticles run` but the mesh, --out and --strict
// (read_mesh takes strict=). Throws UserError for a word it does not know.
RunRequest take_run_request(KeywordOptions& options);

}  // namespace meshparticles::python
