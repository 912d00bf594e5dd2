#include "reports/sweep_report.hpp"

#include <algorithm>
#include <cstdio>

#include "common/atomic_file.hpp"
#include "reports/text_format.hpp"

namespace meshparticles {

namespace {

std::string tile_text(const UpdateKernel& kernel) {
  return kernel.kind == KernelKind::tiled ? std::to_string(kernel.tile_size) : "-";
}

std::string scheme_text(const SweepSettings& settings) {
  return settings.scheme == Scheme::colored ? "colored K=" + std::to_string(settings.colors)
                                            : scheme_name(settings.scheme);
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
  nlohmann::json row = {{"kernel", kernel_kind_name(result.kernel.kind)},
                        {"wg", result.kernel.work_group_size},
                        {"tile", nullptr},
                        {"status", sweep_status_name(result.status)}};
  if (result.kernel.kind == KernelKind::tiled) row["tile"] = result.kernel.tile_size;
  if (result.status == SweepStatus::ok) {
    row["median_ms"] = result.timing.median_ms;
    row["min_ms"] = result.timing.min_ms;
  } else {
    row["reason"] = result.reason;
  }
  return row;
}

}  // namespace

std::string sweep_table(const DeviceDescription& device, const SweepContext& context,
                        const std::vector<SweepResult>& results) {
  std::string text = "sweep on " + device.name + " (max work-group " + std::to_string(device.max_work_group_size) +
                     ", local memory " + std::to_string(device.local_memory_bytes) + " B)\n";
  text += context.mesh_path + " (" + std::to_string(context.vertices) + " vertices), n " +
          std::to_string(context.particles) + ", " + scheme_text(context.settings) +
          "; update kernels per iteration, ms over " + std::to_string(context.settings.repetitions) +
          " timed iterations\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-6s %6s %6s  %-8s %10s %10s  %s\n", "kernel", "wg", "tile", "status", "median",
                "min", "note");
  text += line;
  for (const SweepResult* result : table_order(results)) {
    const bool timed = result->status == SweepStatus::ok;
    std::snprintf(line, sizeof line, "%-6s %6zu %6s  %-8s %10s %10s  ", kernel_kind_name(result->kernel.kind).c_str(),
                  result->kernel.work_group_size, tile_text(result->kernel).c_str(),
                  sweep_status_name(result->status).c_str(),
                  timed ? format_number("%.3f", result->timing.median_ms).c_str() : "-",
                  timed ? format_number("%.3f", result->timing.min_ms).c_str() : "-");
    text += line + result->reason + "\n";
  }
  const SweepResult* naive = best_result(results, KernelKind::naive);
  for (const KernelKind kind : {KernelKind::naive, KernelKind::tiled, KernelKind::field}) {
    const SweepResult* best = best_result(results, kind);
    if (!best) continue;
    text += "\nbest " + kernel_kind_name(kind) + ": " + best->kernel.sizes_text() + ", " +
            format_number("%.3f", best->timing.median_ms) + " ms";
    if (naive && kind != KernelKind::naive) {
      text += " (" + format_number("%.2f", naive->timing.median_ms / best->timing.median_ms) + "x the best naive)";
    }
  }
  if (best_result(results, KernelKind::field)) {
    text += "\nfield: its update kernels plus one rebuild of F (n rows, what an iteration costs when half the "
            "particles move)";
  }
  return text + "\n";
}

nlohmann::json sweep_json(const DeviceDescription& device, const SweepContext& context,
                          const std::vector<SweepResult>& results) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& result : results) rows.push_back(row_json(result));
  nlohmann::json best = nlohmann::json::object();
  for (const KernelKind kind : {KernelKind::naive, KernelKind::tiled, KernelKind::field}) {
    if (const SweepResult* result = best_result(results, kind)) best[kernel_kind_name(kind)] = row_json(*result);
  }
  return {{"device",
           {{"name", device.name},
            {"platform", device.platform_name},
            {"max_work_group_size", device.max_work_group_size},
            {"local_memory_bytes", device.local_memory_bytes},
            {"max_allocation_bytes", device.max_allocation_bytes}}},
          {"mesh", context.mesh_path},
          {"vertices", context.vertices},
          {"n", context.particles},
          {"scheme", scheme_name(context.settings.scheme)},
          {"colors", context.settings.scheme == Scheme::colored ? nlohmann::json(context.settings.colors) : nullptr},
          {"timed_iterations", context.settings.repetitions},
          {"warmup_iterations", context.settings.warmups},
          {"time", "update kernels per iteration, ms, from OpenCL profiling events"},
          {"rows", rows},
          {"best", best}};
}

void write_sweep_csv(const std::filesystem::path& file, const DeviceDescription& device, const SweepContext& context,
                     const std::vector<SweepResult>& results) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "device,max_work_group_size,local_memory_bytes,mesh,n,kernel,wg,tile,status,median_ms,min_ms,reason\n";
    for (const auto& result : results) {
      const bool timed = result.status == SweepStatus::ok;
      out << csv_field(device.name) << ',' << device.max_work_group_size << ',' << device.local_memory_bytes << ','
          << csv_field(context.mesh_path) << ',' << context.particles << ','
          << kernel_kind_name(result.kernel.kind) << ',' << result.kernel.work_group_size << ','
          << (result.kernel.kind == KernelKind::tiled ? std::to_string(result.kernel.tile_size) : "") << ','
          << sweep_status_name(result.status) << ',' << (timed ? format_number("%.6f", result.timing.median_ms) : "")
          << ',' << (timed ? format_number("%.6f", result.timing.min_ms) : "") << ',' << csv_field(result.reason) << '\n';
    }
  });
}

}  // namespace meshparticles
