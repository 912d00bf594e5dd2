#pragma once
// What a batch has done so far, kept by the one process that writes the
// summary (the only one, or rank 0): every mesh's row in input order (pending
// until it is done), summary.csv and summary.json rewritten atomically as
// each mesh finishes, so a batch killed at any moment leaves a summary of
// what it did, and the progress lines on stderr: one per finished mesh, then
// the overall count, rate and time left.
#include <chrono>
#include <mutex>
#include <vector>

#include "batch/mesh_job.hpp"

namespace meshparticles {

class BatchLedger {
 public:
  // Writes the summary with every mesh pending.
  explicit BatchLedger(const BatchPlan& plan);

  // Item `index` is done: its row, the summary files and the progress lines.
  // Safe to call from several threads.
  void record(std::size_t index, const MeshOutcome& outcome);

  // The batch's exit status: 0 when every mesh is ok, 2 when some were
  // refused (and none failed), 1 when one failed or was never done. Prints
  // the closing line.
  int finish();

 private:
  std::string overall_line() const;

  const BatchPlan& plan_;
  std::vector<nlohmann::json> rows_;
  std::size_t done_ = 0, computed_ = 0, reused_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

}  // namespace meshparticles
