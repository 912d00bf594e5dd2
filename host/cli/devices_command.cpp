#include <cstdio>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "common/user_error.hpp"
#include "opencl/device_discovery.hpp"

namespace meshparticles {

namespace {

double mebibytes(cl_ulong bytes) { return double(bytes) / (1024.0 * 1024.0); }

// Lists every device even when the request matches none: the listing is
// what the user needs to fix it.
void run_devices(const std::string& device_option) {
  const auto devices = list_devices();
  const DeviceRequest request = device_request(device_option);
  const std::optional<DeviceDescription> chosen = match_device(devices, request);
  std::printf("%-5s %-11s %-40s %4s %11s %9s %6s  %s\n", "index", "type", "name", "CUs", "global MiB",
              "local KiB", "max wg", "OpenCL C");
  for (const auto& d : devices) {
    std::printf("%-5s %-11s %-40.40s %4u %11.0f %9.0f %6zu  %s%s\n", d.index().c_str(), d.type.c_str(),
                d.name.c_str(), d.compute_units, mebibytes(d.global_memory_bytes),
                double(d.local_memory_bytes) / 1024.0, d.max_work_group_size, d.opencl_c_version.c_str(),
                chosen && d.index() == chosen->index() ? "  (selected)" : "");
  }
  std::fflush(stdout);
  if (chosen) return;
  const std::string problem = request.described() + " matches no device above (give P:D or part of a name)";
  // A bad argument of this command fails; the variable only affects other commands.
  if (request.origin == "--device") throw UserError(problem);
  std::fprintf(stderr, "meshparticles: warning: %s\n", problem.c_str());
}

}  // namespace

void add_devices_command(CLI::App& app) {
  auto device_request = std::make_shared<std::string>();
  CLI::App* devices = app.add_subcommand("devices", "List OpenCL platforms and devices, marking the one selected");
  add_device_option(*devices, *device_request);
  devices->callback([device_request] { run_devices(*device_request); });
}

}  // namespace meshparticles
