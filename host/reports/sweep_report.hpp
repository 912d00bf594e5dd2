#pragma once
// What `meshparticles sweep` prints and writes: a table with the fastest
// configuration last, and the same rows as CSV and JSON (device and its
// limits, mesh, n, kernel, wg, tile, status, median and minimum ms).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "measurement/sweep.hpp"

namespace meshparticles {

std::string sweep_table(const SweepOutcome& sweep);
nlohmann::json sweep_json(const SweepOutcome& sweep);
void write_sweep_csv(const std::filesystem::path& file, const SweepOutcome& sweep);

}  // namespace meshparticles
