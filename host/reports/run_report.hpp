#pragma once
// report.json of a run, built from the pipeline's result.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// report.json: the mesh (with the SHA-256 of the file it was read from,
// when there was one), every parameter in effect (with where the kernel
// sizes came from), the device, the trace, timings and quality. `out`: the
// output directory, recorded among the parameters.
nlohmann::json run_report(const SurfaceMesh& mesh, const RunResult& result, const std::filesystem::path& out,
                          const std::optional<std::string>& mesh_sha256);

// report.json's "params": every option of the plan in effect, defaults
// resolved. A resumed batch compares it with a stored report's.
nlohmann::json run_parameters(const RunPlan& plan, const std::filesystem::path& out);

}  // namespace meshparticles
