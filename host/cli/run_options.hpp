#pragma once
// The options of one run, shared by `run` (one mesh) and `batch` (the same
// run on many): each row of options/run_option_table registered once, into
// RunOptionValues, which run_request (options/run_option_values.hpp) resolves.
#include <CLI/CLI.hpp>

#include "options/run_option_values.hpp"

namespace meshparticles {

// Every option of a run but the mesh and --out: -n, --iterations, --backend,
// --scheme, ..., --strict, the distance table's options and -q.
void add_run_options(CLI::App& command, RunOptionValues& options);

}  // namespace meshparticles
