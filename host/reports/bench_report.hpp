#pragma once
// What `meshparticles bench` prints and writes: per mesh, a block in the
// layout of the paper's Tables 1 and 2 (a row per backend: serial, naive, tiled, field, columns
// particle counts) with our figure, its speed-up over our serial row, and
// the paper's figure and speed-up beside it; the same as CSV and JSON.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "opencl/device_discovery.hpp"
#include "measurement/bench.hpp"

namespace meshparticles {

std::string bench_tables(const std::string& device_name, const BenchSettings& settings,
                         const std::vector<BenchCase>& cases);
nlohmann::json bench_json(const std::string& device_name, const BenchSettings& settings,
                          const std::vector<BenchCase>& cases);
void write_bench_csv(const std::filesystem::path& file, const std::string& device_name,
                     const BenchSettings& settings, const std::vector<BenchCase>& cases);

}  // namespace meshparticles
