#pragma once
// `meshparticles bench`: average time per iteration of each backend on one
// problem, the way the paper's Tables 1 and 2 measured it. The serial row is
// the paper's CPU loop (sequential scheme; serial-field too); the device rows
// run the scheme a `run` would, with the sizes a `run` would take (tuning
// file or default).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "measurement/bench_plan.hpp"
#include "measurement/timing_statistics.hpp"

namespace meshparticles {

struct BenchSettings {
  Scheme device_scheme = Scheme::monotone;
  unsigned colors = kDefaultColors;
  std::size_t iterations = 20;  // timed; the paper used 1000
  std::size_t warmups = 1;      // untimed first (PoCL compiles at the first launch)
};

struct BenchRow {
  std::string backend;  // serial, serial-field, naive, tiled, field
  Scheme scheme = Scheme::sequential;
  std::string sizes;       // "wg 64 tile 128", empty for serial
  std::string sizes_from;  // tuning file, built-in default
  double mean_ms = 0;      // wall time per iteration, as the paper reports
  TimingSummary timing;    // the same samples' median and minimum
  std::optional<double> kernel_ms;  // update kernels per iteration (device rows), mean
  double moved_mean = 0;            // particles moved per timed iteration, mean
};

struct BenchCase {
  std::string mesh;  // name: sphere, torus, atrium
  std::size_t vertices = 0;
  std::size_t particles = 0;
  std::vector<BenchRow> rows;
};

// Times every backend of every case of `plan` (one row each) on
// farthest-point-placed particles, with a progress line.
std::vector<BenchCase> run_bench(const BenchPlan& plan, const BenchSettings& settings);

}  // namespace meshparticles
