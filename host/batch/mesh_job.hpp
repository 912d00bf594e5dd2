#pragma once
// One mesh of a batch: the single code path that every process and rank
// runs for a mesh, and that yields its summary row.
#include <nlohmann/json.hpp>

#include "batch/batch_plan.hpp"

namespace meshparticles {

struct MeshOutcome {
  nlohmann::json row;   // reports/batch_summary.hpp
  bool reused = false;  // an earlier output was valid and kept
};

// Reads the mesh, plans its run and, unless --force, keeps an earlier
// output that can stand for it (batch/reusable_output.hpp); else runs the
// pipeline and writes the run's files as one set, exactly as `run` would.
// A problem of this mesh never escapes: it is the row's status and reason
// (refused: the user can act on it; failed: a bug).
MeshOutcome run_batch_mesh(const BatchPlan& plan, std::size_t index);

// The row of a mesh whose run was lost with the process running it: failed,
// for `reason`; a resume runs it again.
MeshOutcome lost_mesh_outcome(const BatchPlan& plan, std::size_t index, const std::string& reason);

}  // namespace meshparticles
