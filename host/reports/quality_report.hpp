#pragma once
// The metrics of distribution_quality.hpp as people and programs read them:
// report.json's "quality" object, a run's one-line summary, and the table of
// `quality` and `compare`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/point_set_measurement.hpp"
#include "quality/particle_sets.hpp"

namespace meshparticles {

// Keys nn_min, nn_mean, nn_std, nn_cv, rho, cover, energy, stacked (null
// where a value is absent), plus d_hex.
nlohmann::json quality_json(const DistributionQuality& quality);
// quality_json's object read back (with `particles` for the count it lacks);
// every double as it was written.
DistributionQuality quality_from_json(const nlohmann::json& json, std::size_t particles);

// "nn min 0.0723 mean 0.0981 cv 0.071, rho 0.74, cover 0.93, energy 632.1, 0 stacked".
std::string quality_line(const DistributionQuality& quality);

nlohmann::json measured_set_json(const MeasuredSet& set);

// What `quality --json` (one set) and `compare --json` (two: "a", "b" and
// the mean distances between them) print.
nlohmann::json point_sets_json(const std::string& mesh_label, const PointSetsMeasurement& measured);

// The metrics as a table, one column per set.
std::string quality_table(const std::vector<const MeasuredSet*>& sets);

}  // namespace meshparticles
