#pragma once
// Finding OpenCL devices: the one place that enumerates platforms, describes
// devices and picks the one a command runs on.
#include <string>
#include <vector>

#include "opencl/opencl.hpp"

namespace meshparticles {

struct DeviceDescription {
  std::size_t platform_index = 0;
  std::size_t device_index = 0;
  std::string platform_name;
  std::string name;
  std::string type;  // "GPU", "CPU", "accelerator", "other"
  cl_uint compute_units = 0;
  cl_ulong global_memory_bytes = 0;
  cl_ulong max_allocation_bytes = 0;
  cl_ulong local_memory_bytes = 0;
  std::size_t max_work_group_size = 0;
  std::string opencl_c_version;
  cl::Device device;

  std::string index() const { return std::to_string(platform_index) + ":" + std::to_string(device_index); }
};

// Every device of every platform. Throws UserError (naming the package to
// install) when there is no OpenCL runtime or no device at all.
std::vector<DeviceDescription> list_devices();

// The device named by `request` ("P:D", or a case-insensitive substring of
// the device or platform name); when empty, by $MESHPARTICLES_DEVICE; otherwise the first GPU,
// else the first device. Throws UserError when nothing matches.
DeviceDescription select_device(const std::string& request);

}  // namespace meshparticles
