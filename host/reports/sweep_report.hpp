#pragma once
// What `meshparticles sweep` prints and writes: a table with the fastest
// configuration last, and the same rows as CSV and JSON (device and its
// limits, mesh, n, kernel, wg, tile, status, median and minimum ms).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "opencl/device_discovery.hpp"
#include "tuning/sweep.hpp"

namespace meshparticles {

struct SweepContext {
  std::string mesh_path;
  std::size_t vertices = 0;
  std::size_t particles = 0;
  SweepSettings settings;
};

std::string sweep_table(const DeviceDescription& device, const SweepContext& context,
                        const std::vector<SweepResult>& results);
nlohmann::json sweep_json(const DeviceDescription& device, const SweepContext& context,
                          const std::vector<SweepResult>& results);
void write_sweep_csv(const std::filesystem::path& file, const DeviceDescription& device, const SweepContext& context,
                     const std::vector<SweepResult>& results);

}  // namespace meshparticles
