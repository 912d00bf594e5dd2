#pragma once
// `meshparticles sweep`: every (kernel, work-group size, tile size) is checked
// against the device's and the compiled kernel's limits, verified against the
// serial reference on the same positions, and only then timed. Like a run,
// in two steps: plan_sweep refuses what cannot run before the distances are
// computed; run_sweep measures.
#include <optional>
#include <string>
#include <vector>

#include "backends/update_kernel.hpp"
#include "geodesics/distance_cache.hpp"
#include "measurement/timing_statistics.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/potentials.hpp"

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

// The sizes swept when none are given.
inline const std::vector<std::size_t> kSweepWorkGroupSizes = {8, 16, 32, 64, 128, 256};
inline const std::vector<std::size_t> kSweepTileSizes = {16, 32, 64, 128, 256, 512, 1024};

struct SweepRequest {
  std::string mesh_label;
  std::size_t particles = 1024;
  std::vector<std::string> kernels;  // device backends; each once, in this order
  std::vector<std::size_t> work_group_sizes = kSweepWorkGroupSizes;
  std::optional<std::vector<std::size_t>> tile_sizes;  // kernels that take a tile; default kSweepTileSizes
  std::optional<WeightFormat> weights;  // kernels that take a weight format; default float32
  Init init = Init::farthest;
  std::uint64_t seed = 1;
  Potential potential = kDefaultPotential;
  std::string device;
  GeodesicsRequest geodesics;
  SweepSettings settings;
};

struct SweepPlan {
  SweepRequest request;
  std::size_t vertices = 0;  // of the mesh
  DeviceDescription device;
  EnergyParams energy;
  std::vector<UpdateKernel> configurations;
};

struct SweepOutcome {
  SweepPlan plan;
  std::vector<SweepResult> results;  // in the order of plan.configurations
};

// Each kernel with each work-group size, and with each tile size where it
// takes one (duplicates dropped).
std::vector<UpdateKernel> sweep_configurations(const std::vector<std::string>& kernels,
                                               const std::vector<std::size_t>& work_group_sizes,
                                               const std::vector<std::size_t>& tile_sizes,
                                               std::size_t candidate_slots, WeightFormat weights);

// Throws UserError for unknown kernels, n out of range, --tile or --weights
// where no swept kernel takes them, no timed iteration, no device.
SweepPlan plan_sweep(const SurfaceMesh& mesh, const SweepRequest& request);

// Distances, start and every configuration, with a progress line.
SweepOutcome run_sweep(const SurfaceMesh& mesh, const SweepPlan& plan);

// Measures `configurations` on `positions` (what run_sweep does once it has
// the distances and the start).
std::vector<SweepResult> measure_configurations(const DeviceDescription& device, const SurfaceMesh& mesh,
                                                const DistanceStore& distances, const EnergyParams& energy,
                                                const std::vector<VertexId>& positions,
                                                const std::vector<UpdateKernel>& configurations,
                                                const SweepSettings& settings);

// The fastest `ok` result of `kernel`, if any.
const SweepResult* best_result(const std::vector<SweepResult>& results, const std::string& kernel);

}  // namespace meshparticles
