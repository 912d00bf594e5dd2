#include "batch/node_share.hpp"

#include "backends/backend_table.hpp"
#include "common/user_error.hpp"
#include "launch/launch_environment.hpp"
#include "opencl/device_discovery.hpp"

namespace meshparticles {

void share_node(RunRequest& run, int local_rank, int local_size) {
  unsigned& threads = run.distances.geodesics.threads;
  if (threads == 0) threads = cores_per_rank(local_size);
  // An empty name is the default backend, on a device or not by the store (plan_run).
  const bool may_use_device = run.backend.name.empty() || find_backend(run.backend.name).on_device();
  if (!may_use_device || !device_request(run.backend.device).text.empty()) return;
  std::vector<DeviceDescription> gpus;
  try {
    gpus = list_devices();
  } catch (const UserError&) {
    // No OpenCL runtime: a device backend named outright says so at its plan,
    // the default one may well run on the host.
    if (!run.backend.name.empty()) throw;
    return;
  }
  std::erase_if(gpus, [](const DeviceDescription& device) { return !device.is_gpu(); });
  if (!gpus.empty()) run.backend.device = gpus[std::size_t(local_rank) % gpus.size()].index();
}

}  // namespace meshparticles
