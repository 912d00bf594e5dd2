#pragma once
// report.json of a run, built from the pipeline's result.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// report.json: the mesh, every parameter in effect (with where the kernel
// sizes came from), the device, the trace, timings and quality. `out`: the
// output directory, recorded among the parameters.
nlohmann::json run_report(const SurfaceMesh& mesh, const RunResult& result, const std::filesystem::path& out);

}  // namespace meshparticles
