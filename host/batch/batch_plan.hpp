#pragma once
// A batch as a library call: many meshes, the same run on each, one output
// folder per mesh and a summary (docs/BATCH.md). plan_batch finds the
// meshes, names their folders and checks --out before any work.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "batch/particle_count.hpp"
#include "common/directory_lock.hpp"
#include "launch/batch_inputs.hpp"
#include "mesh/mesh_checks.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

struct BatchRequest {
  std::vector<std::string> inputs;  // mesh files, folders, .txt lists
  std::filesystem::path out;        // one folder per mesh in it, and summary.csv and summary.json
  RunRequest run;                   // every mesh's run; its mesh_label and particles are set per mesh
  ParticleCount count;              // the particles of each mesh
  MeshReadOptions read;
  bool force = false;  // recompute meshes whose earlier outputs are complete and valid
  bool quiet = false;  // no progress lines or warnings on stderr
  // Under MPI: a rank not heard from for this long is taken for dead, and
  // the mesh it was running is marked failed (batch/mpi_work_queue.hpp).
  double rank_timeout_seconds = 60;
};

struct BatchItem {
  MeshInput input;
  std::string output_name;  // the mesh's folder in --out (batch/output_names.hpp)
};

struct BatchPlan {
  BatchRequest request;
  std::vector<BatchItem> items;  // in the order of the inputs
  // --out held for this batch alone while the plan lives (on the process
  // that writes the summary): two batches into one folder would each
  // rewrite the summary and leave one that is neither's.
  std::shared_ptr<const DirectoryLock> out_lock;
};

// Throws UserError for inputs that name no mesh, a folder or list that
// cannot be read, and an --out that cannot be written or that another
// batch holds (when `lock_out`). Prints a note for each mesh given twice
// unless quiet.
BatchPlan plan_batch(const BatchRequest& request, bool lock_out);

// The output folder of item `index`.
std::filesystem::path output_directory(const BatchPlan& plan, std::size_t index);

}  // namespace meshparticles
