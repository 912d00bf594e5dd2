#pragma once
// `meshparticles sweep`: every (kernel, work-group size, tile size) is checked
// against the device's and the compiled kernel's limits, verified against the
// serial reference on the same positions, and only then timed.
#include <span>
#include <string>
#include <vector>

#include "backends/update_kernel.hpp"
#include "geodesics/distance_table.hpp"
#include "opencl/device_discovery.hpp"
#include "tuning/timing_statistics.hpp"

namespace meshparticles {

enum class SweepStatus { ok, skipped, failed };
std::string sweep_status_name(SweepStatus status);  // "ok", "skipped", "FAILED"

struct SweepResult {
  UpdateKernel kernel;
  SweepStatus status = SweepStatus::ok;
  std::string reason;     // skipped or FAILED: why, in one line
  TimingSummary timing;   // ok: update kernels per iteration, ms
};

struct SweepSettings {
  Scheme scheme = Scheme::colored;
  unsigned colors = 16;
  std::size_t repetitions = 20;  // timed iterations per configuration
  std::size_t warmups = 2;       // untimed first (PoCL compiles at the first launch)
  bool quiet = false;
};

// naive, field: one configuration per work-group size (tiles do not apply);
// tiled: every work-group size with every tile size.
std::vector<UpdateKernel> sweep_configurations(const std::vector<KernelKind>& kinds,
                                               const std::vector<std::size_t>& work_group_sizes,
                                               const std::vector<std::size_t>& tile_sizes,
                                               std::size_t candidate_slots);

// Results in the order of `configurations`. Shows a progress line.
std::vector<SweepResult> run_sweep(const DeviceDescription& device, const SurfaceMesh& mesh,
                                   const DistanceTable& distances, const EnergyParams& energy,
                                   const std::vector<VertexId>& positions,
                                   const std::vector<UpdateKernel>& configurations, const SweepSettings& settings);

// The fastest `ok` result of `kind`, if any.
const SweepResult* best_result(const std::vector<SweepResult>& results, KernelKind kind);

}  // namespace meshparticles
