#include "batch/mesh_queue.hpp"

#include <algorithm>
#include <numeric>

namespace meshparticles {

std::optional<std::size_t> LedgerQueue::next() {
  const std::lock_guard lock(mutex_);
  if (handed_out_ == order_.size()) return std::nullopt;
  return order_[handed_out_++];
}

void LedgerQueue::finished(std::size_t index, const MeshOutcome& outcome) { ledger_.record(index, outcome); }

std::vector<std::size_t> input_order(const BatchPlan& plan) {
  std::vector<std::size_t> order(plan.items.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  return order;
}

std::vector<std::size_t> biggest_first_order(const BatchPlan& plan) {
  std::vector<std::size_t> order = input_order(plan);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return plan.items[a].input.bytes > plan.items[b].input.bytes;
  });
  return order;
}

void work_through(const BatchPlan& plan, MeshQueue& queue) {
  while (const std::optional<std::size_t> index = queue.next()) queue.finished(*index, run_batch_mesh(plan, *index));
}

}  // namespace meshparticles
