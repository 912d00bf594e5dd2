#pragma once
// `meshparticles bench --quality`: how even each way of placing n particles
// is, on one problem, in one table - the baselines (random vertices,
// farthest-point sampling alone, the paper's start with its sequential
// loop) and our default pipeline on each backend (docs/QUALITY.md). Every
// run goes through the pipeline (pipeline/run_pipeline.hpp).
#include <optional>
#include <string>
#include <vector>

#include "measurement/bench_plan.hpp"
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

// Rows added to each case beside one per backend: random, farthest, the paper's.
inline constexpr std::size_t kQualityBaselineRows = 3;

// Per case: the start rows, the paper's start iterated by the serial backend
// (sequential), and one default-pipeline row per backend of the plan
// (farthest start, monotone K = 16 on devices and on serial alike, at most
// `max_iterations`).
std::vector<QualityCase> run_quality_bench(const BenchPlan& plan, std::size_t max_iterations);

}  // namespace meshparticles
