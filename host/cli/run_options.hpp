#pragma once
// The options of one run, shared by `run` (one mesh) and `batch` (the same
// run on many): registered once, resolved into a RunRequest once.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "particles/potentials.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

struct RunOptions {
  MeshReadOptions read;
  RunRequest request;  // numbers go straight in; the words below are resolved by resolved_request
  std::string method;  // default: spread, unless a paper-only option implies paper
  std::string scheme;  // default: the backend's
  std::string init = "farthest";
  std::string potential = potential_name(kDefaultPotential);
  std::string geodesic;  // default: fmm, or fim where the paper method's default gives a GPU the balls
  std::string weights;
  DistanceStoreOptions store;
  std::string tuning_file;
  DistanceTableOptions table;

  // The request with every word resolved. Throws UserError.
  RunRequest resolved_request() const;
};

// Every option of a run but the mesh and --out: -n, --iterations, --backend,
// --scheme, ..., --strict, the distance table's options and -q.
void add_run_options(CLI::App& command, RunOptions& options);

}  // namespace meshparticles
