#pragma once
// Who hands out a batch's meshes: the process's own list, or (with MPI)
// rank 0 for every rank. Every process runs the same loop over a queue,
// work_through, so one process and many ranks do each mesh the same way.
#include <cstddef>
#include <mutex>
#include <optional>
#include <vector>

#include "batch/batch_ledger.hpp"
#include "batch/mesh_job.hpp"

namespace meshparticles {

class MeshQueue {
 public:
  virtual ~MeshQueue() = default;
  // The next item to run, or nothing when all are handed out.
  virtual std::optional<std::size_t> next() = 0;
  virtual void finished(std::size_t index, const MeshOutcome& outcome) = 0;
};

// The items in a fixed order, each outcome recorded in the ledger. Safe to
// share between threads (rank 0's own work and its dispatcher).
class LedgerQueue : public MeshQueue {
 public:
  LedgerQueue(std::vector<std::size_t> order, BatchLedger& ledger) : order_(std::move(order)), ledger_(ledger) {}
  std::optional<std::size_t> next() override;
  void finished(std::size_t index, const MeshOutcome& outcome) override;

 private:
  std::vector<std::size_t> order_;
  std::size_t handed_out_ = 0;
  BatchLedger& ledger_;
  std::mutex mutex_;
};

// Input order: how one process goes through the meshes.
std::vector<std::size_t> input_order(const BatchPlan& plan);
// Biggest file first, ties in input order: how ranks share them, so that no
// rank starts the longest mesh last while the others sit idle.
std::vector<std::size_t> biggest_first_order(const BatchPlan& plan);

// Runs items from `queue` until it has none left.
void work_through(const BatchPlan& plan, MeshQueue& queue);

}  // namespace meshparticles
