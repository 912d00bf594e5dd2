#include "batch/node_share.hpp"

#include <algorithm>
#include <thread>

#include "backends/backend_table.hpp"
#include "opencl/device_discovery.hpp"

namespace meshparticles {

void share_node(RunRequest& run, int local_rank, int local_size) {
  unsigned& threads = run.distances.geodesics.threads;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency() / unsigned(std::max(local_size, 1)));
  if (!find_backend(run.backend.name).on_device() || !device_request(run.backend.device).text.empty()) return;
  std::vector<DeviceDescription> gpus = list_devices();
  std::erase_if(gpus, [](const DeviceDescription& device) { return device.type != "GPU"; });
  if (!gpus.empty()) run.backend.device = gpus[std::size_t(local_rank) % gpus.size()].index();
}

}  // namespace meshparticles
