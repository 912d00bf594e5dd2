#pragma once
// `meshparticles bench --quality`: how even each way of placing n particles
// is, on one problem, in one table - the baselines (random vertices,
// farthest-point sampling alone, the paper's start with its sequential
// loop) and our default pipeline on each backend (docs/QUALITY.md).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend_factory.hpp"
#include "geodesics/distance_table.hpp"
#include "quality/distribution_quality.hpp"

namespace meshparticles {

struct QualityRow {
  std::string method;   // "random", "farthest", "paper: v0 + sequential", "default"
  std::string backend;  // the backend that iterated; empty for a start alone
  std::size_t iterations = 0;
  bool converged = false;
  DistributionQuality quality;
  // default rows: energy relative to the serial backend's default row, (E - E_serial) / E_serial
  std::optional<double> energy_vs_serial;
};

struct QualityCase {
  std::string mesh;
  std::size_t vertices = 0;
  std::size_t particles = 0;
  double sigma = 0;
  std::vector<QualityRow> rows;
};

// The start rows, the paper's start iterated by the serial backend
// (sequential), and one default-pipeline row per backend in `backends`
// (farthest start, colored K = 16 on devices and on serial alike, at most
// `max_iterations`). `on_row` is called before each row (progress).
QualityCase quality_case(const std::string& mesh_name, const SurfaceMesh& mesh, const DistanceTable& distances,
                         std::size_t particles, const std::vector<CheckedBackend>& backends,
                         std::size_t max_iterations, const std::function<void(const std::string&)>& on_row);

std::string quality_tables(const std::vector<QualityCase>& cases);
nlohmann::json quality_bench_json(const std::vector<QualityCase>& cases);

}  // namespace meshparticles
