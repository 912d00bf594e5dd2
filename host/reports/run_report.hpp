#pragma once
// report.json of a run, built from the pipeline's result.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <cstddef>
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

// The key of report.json that holds a run's record per iteration: paper's
// "trace" (energy, moved, ms, ...), spread's "sweeps" (moved, ms, spacings).
const char* iteration_records_key(Method method);

// What a run's iterations came to, as report.json records it and `run`
// prints it: paper's iterations, spread's sweeps.
struct IterationFigures {
  std::size_t iterations_run = 0;
  std::string stopped;                   // converged, max_iterations, or spread's cycle or stalled
  std::optional<double> initial_energy;  // paper: the start's
  double final_energy = 0;               // paper: the last iteration's; spread: the quality's, within its cutoff
  double avg_iteration_ms = 0;
  std::optional<double> avg_kernel_ms;   // paper, where the backend times its update kernels
};
IterationFigures iteration_figures(const RunResult& result);

}  // namespace meshparticles
