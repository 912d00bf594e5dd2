#include "batch/batch_ledger.hpp"

#include <iostream>
#include <map>

#include "common/text_format.hpp"
#include "reports/batch_summary.hpp"

namespace meshparticles {

namespace {

std::string duration_text(double seconds) {
  if (seconds < 120) return format_number("%.0f s", seconds);
  if (seconds < 7200) return format_number("%.1f min", seconds / 60);
  return format_number("%.1f h", seconds / 3600);
}

std::string mesh_line(const nlohmann::json& row, bool reused) {
  const std::string status = row.at("status");
  if (status != "ok") return status + ": " + row.at("reason").get<std::string>();
  // A kept output's figures are its earlier run's, seconds included.
  const std::string kept = reused ? " (kept: an earlier output, complete and valid)" : "";
  return "ok" + kept + ", " + std::to_string(row.at("vertices").get<std::size_t>()) + " vertices, n " +
         std::to_string(row.at("n").get<std::size_t>()) + ", " +
         std::to_string(row.at("iterations").get<std::size_t>()) + " iterations" +
         (row.at("converged").get<bool>() ? " (converged)" : " (iteration limit)") + ", " +
         format_number("%.2f s", row.at("seconds_total").get<double>());
}

}  // namespace

BatchLedger::BatchLedger(const BatchPlan& plan) : plan_(plan), start_(std::chrono::steady_clock::now()) {
  for (const BatchItem& item : plan.items) rows_.push_back(pending_row(item.input.path.string(), item.output_name));
  write_batch_summary(plan.request.out, rows_);
}

std::string BatchLedger::overall_line() const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line = "batch: " + std::to_string(done_) + " of " + std::to_string(rows_.size()) + " meshes done";
  if (computed_ == 0) return line;
  // Meshes kept from an earlier batch cost next to nothing: the rate is of those computed.
  const double per_minute = 60.0 * double(computed_) / elapsed;
  return line + ", " + format_number("%.2f", per_minute) + " meshes/min, about " +
         duration_text(double(rows_.size() - done_) * 60.0 / per_minute) + " left";
}

void BatchLedger::record(std::size_t index, const MeshOutcome& outcome) {
  const std::lock_guard lock(mutex_);
  // A mesh recorded twice (lost with a rank taken for dead, then reported
  // by it after all) counts once.
  if (row_status(rows_[index]) == MeshStatus::pending) ++done_;
  rows_[index] = outcome.row;
  ++(outcome.reused ? reused_ : computed_);
  write_batch_summary(plan_.request.out, rows_);
  if (plan_.request.quiet) return;
  std::cerr << "meshparticles: [" << done_ << "/" << rows_.size() << "] " << plan_.items[index].output_name << ": "
            << mesh_line(outcome.row, outcome.reused) << "\n"
            << "meshparticles: " << overall_line() << "\n";
}

int BatchLedger::finish() {
  const std::lock_guard lock(mutex_);
  std::map<MeshStatus, std::size_t> counts;
  for (const nlohmann::json& row : rows_) ++counts[row_status(row)];
  if (!plan_.request.quiet) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::cerr << "meshparticles: batch: " << rows_.size() << " meshes in " << duration_text(elapsed) << ": "
              << counts[MeshStatus::ok] << " ok (" << reused_ << " kept from an earlier batch), "
              << counts[MeshStatus::refused] << " refused, " << counts[MeshStatus::failed] << " failed; summary in "
              << (plan_.request.out / "summary.csv").string() << "\n";
  }
  if (counts[MeshStatus::failed] > 0 || counts[MeshStatus::pending] > 0) return 1;
  return counts[MeshStatus::refused] > 0 ? 2 : 0;
}

}  // namespace meshparticles
