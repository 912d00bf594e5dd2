#pragma once
// Finding OpenCL devices: the one place that enumerates platforms, describes
// devices and picks the one a command runs on.
#include <optional>
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
  // Where the device paths pay by default (a CPU device shares the host's cores).
  bool is_gpu() const { return type == "GPU"; }
};

// The exit code of a run that needs OpenCL where no runtime is usable.
inline constexpr int kNoRuntimeExitCode = 3;

// Every device of every platform. Throws UserError (naming the package to
// install) when there is no OpenCL runtime or no device at all.
std::vector<DeviceDescription> list_devices();

// What the user asked for and where it came from, for messages.
struct DeviceRequest {
  std::string text;    // "P:D" or part of a name; empty: the default rule
  std::string origin;  // "--device" or "$MESHPARTICLES_DEVICE"
  std::string described() const;  // "$MESHPARTICLES_DEVICE='bogus'"
};

// --device when given, else $MESHPARTICLES_DEVICE, else nothing (the default rule).
DeviceRequest device_request(const std::string& option);

// The device `request` names ("P:D", or a case-insensitive substring of the
// device or platform name); with an empty request the first GPU, else the
// first device; nothing when no device matches.
std::optional<DeviceDescription> match_device(const std::vector<DeviceDescription>& devices,
                                              const DeviceRequest& request);

// match_device over list_devices() for --device `option` (or the
// environment); throws UserError naming the option or the variable when
// nothing matches.
DeviceDescription select_device(const std::string& option);

}  // namespace meshparticles
