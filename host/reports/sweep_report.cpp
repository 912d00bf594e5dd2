#include "reports/sweep_report.hpp"

#include <algorithm>
#include <cstdio>

#include "backends/backend_table.hpp"
#include "common/atomic_file.hpp"
#include "common/text_format.hpp"

namespace meshparticles {

namespace {

std::string tile_text(const UpdateKernel& kernel) {
  return kernel.spec().takes_tile ? std::to_string(kernel.tile_size) : "-";
}

std::string scheme_text(const SweepSettings& settings) {
  return settings.scheme == Scheme::colored ? "colored K=" + std::to_string(settings.colors)
                                            : scheme_name(settings.scheme);
}

// The swept kernels in the order of the sweep.
std::vector<std::string> kernels_of(const std::vector<SweepResult>& results) {
  std::vector<std::string> kernels;
  for (const auto& result : results) {
    if (std::find(kernels.begin(), kernels.end(), result.kernel.name()) == kernels.end()) {
      kernels.push_back(result.kernel.name());
    }
  }
  return kernels;
}

// Not timed first (in sweep order), then the timed ones slowest first, so
// the best configuration is the last row.
std::vector<const SweepResult*> table_order(const std::vector<SweepResult>& results) {
  std::vector<const SweepResult*> order;
  for (const auto& result : results) order.push_back(&result);
  std::stable_sort(order.begin(), order.end(), [](const SweepResult* a, const SweepResult* b) {
    const bool a_timed = a->status == SweepStatus::ok, b_timed = b->status == SweepStatus::ok;
    if (a_timed != b_timed) return !a_timed;
    return a_timed && a->timing.median_ms > b->timing.median_ms;
  });
  return order;
}

nlohmann::json row_json(const SweepResult& result) {
  nlohmann::json row = {{"kernel", result.kernel.name()},
                        {"wg", result.kernel.work_group_size},
                        {"tile", nullptr},
                        {"status", sweep_status_name(result.status)}};
  if (result.kernel.spec().takes_tile) row["tile"] = result.kernel.tile_size;
  if (result.status == SweepStatus::ok) {
    row["median_ms"] = result.timing.median_ms;
    row["min_ms"] = result.timing.min_ms;
  } else {
    row["reason"] = result.reason;
  }
  return row;
}

}  // namespace

std::string sweep_table(const SweepOutcome& sweep) {
  const DeviceDescription& device = sweep.plan.device;
  const SweepRequest& request = sweep.plan.request;
  const std::vector<SweepResult>& results = sweep.results;
  std::string text = "sweep on " + device.name + " (max work-group " + std::to_string(device.max_work_group_size) +
                     ", local memory " + std::to_string(device.local_memory_bytes) + " B)\n";
  text += request.mesh_label + " (" + std::to_string(sweep.plan.vertices) + " vertices), n " +
          std::to_string(request.particles) + ", " + scheme_text(request.settings) +
          "; update kernels per iteration, ms over " + std::to_string(request.settings.repetitions) +
          " timed iterations\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-6s %6s %6s  %-8s %10s %10s  %s\n", "kernel", "wg", "tile", "status", "median",
                "min", "note");
  text += line;
  for (const SweepResult* result : table_order(results)) {
    const bool timed = result->status == SweepStatus::ok;
    std::snprintf(line, sizeof line, "%-6s %6zu %6s  %-8s %10s %10s  ", result->kernel.name().c_str(),
                  result->kernel.work_group_size, tile_text(result->kernel).c_str(),
                  sweep_status_name(result->status).c_str(),
                  timed ? format_number("%.3f", result->timing.median_ms).c_str() : "-",
                  timed ? format_number("%.3f", result->timing.min_ms).c_str() : "-");
    text += line + result->reason + "\n";
  }
  // The paper's naive kernel is the baseline the others are measured against.
  const SweepResult* baseline = nullptr;
  for (const std::string& kernel : kernels_of(results)) {
    if (find_backend(kernel).paper_row == PaperRow::gpu1_naive) baseline = best_result(results, kernel);
  }
  std::string notes;
  for (const std::string& kernel : kernels_of(results)) {
    const SweepResult* best = best_result(results, kernel);
    if (!best) continue;
    text += "\nbest " + kernel + ": " + best->kernel.sizes_text() + ", " +
            format_number("%.3f", best->timing.median_ms) + " ms";
    if (baseline && best != baseline) {
      text += " (" + format_number("%.2f", baseline->timing.median_ms / best->timing.median_ms) + "x the best " +
              baseline->kernel.name() + ")";
    }
    if (find_backend(kernel).field_method) {
      notes += "\n" + kernel + ": its update kernels plus one rebuild of F (n rows, what an iteration costs when "
               "half the particles move)";
    }
  }
  return text + notes + "\n";
}

nlohmann::json sweep_json(const SweepOutcome& sweep) {
  const DeviceDescription& device = sweep.plan.device;
  const SweepRequest& request = sweep.plan.request;
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& result : sweep.results) rows.push_back(row_json(result));
  nlohmann::json best = nlohmann::json::object();
  for (const std::string& kernel : kernels_of(sweep.results)) {
    if (const SweepResult* result = best_result(sweep.results, kernel)) best[kernel] = row_json(*result);
  }
  return {{"device",
           {{"name", device.name},
            {"platform", device.platform_name},
            {"max_work_group_size", device.max_work_group_size},
            {"local_memory_bytes", device.local_memory_bytes},
            {"max_allocation_bytes", device.max_allocation_bytes}}},
          {"mesh", request.mesh_label},
          {"vertices", sweep.plan.vertices},
          {"n", request.particles},
          {"scheme", scheme_name(request.settings.scheme)},
          {"colors", request.settings.scheme == Scheme::colored ? nlohmann::json(request.settings.colors) : nullptr},
          {"timed_iterations", request.settings.repetitions},
          {"warmup_iterations", request.settings.warmups},
          {"time", "update kernels per iteration, ms, from OpenCL profiling events"},
          {"rows", rows},
          {"best", best}};
}

void write_sweep_csv(const std::filesystem::path& file, const SweepOutcome& sweep) {
  const DeviceDescription& device = sweep.plan.device;
  const SweepRequest& request = sweep.plan.request;
  write_file_atomically(file, [&](std::ostream& out) {
    out << "device,max_work_group_size,local_memory_bytes,mesh,n,kernel,wg,tile,status,median_ms,min_ms,reason\n";
    for (const auto& result : sweep.results) {
      const bool timed = result.status == SweepStatus::ok;
      out << csv_field(device.name) << ',' << device.max_work_group_size << ',' << device.local_memory_bytes << ','
          << csv_field(request.mesh_label) << ',' << request.particles << ',' << result.kernel.name() << ','
          << result.kernel.work_group_size << ','
          << (result.kernel.spec().takes_tile ? std::to_string(result.kernel.tile_size) : "") << ','
          << sweep_status_name(result.status) << ',' << (timed ? format_number("%.6f", result.timing.median_ms) : "")
          << ',' << (timed ? format_number("%.6f", result.timing.min_ms) : "") << ',' << csv_field(result.reason) << '\n';
    }
  });
}

}  // namespace meshparticles
