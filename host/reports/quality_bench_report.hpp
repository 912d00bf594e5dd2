#pragma once
// What `meshparticles bench --quality` prints and writes: per case, a table
// of the placements' metrics; the same as JSON.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "measurement/quality_bench.hpp"

namespace meshparticles {

std::string quality_tables(const std::vector<QualityCase>& cases);
nlohmann::json quality_bench_json(const std::vector<QualityCase>& cases);

}  // namespace meshparticles
