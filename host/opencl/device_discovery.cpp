#include "opencl/device_discovery.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "common/user_error.hpp"
#include "opencl/runtime_environment.hpp"

namespace meshparticles {

namespace {

const std::string kInstallHint =
    "install an OpenCL runtime (on Debian: apt-get install pocl-opencl-icd for the CPU, or your GPU vendor's ICD)";

std::string type_name(cl_device_type type) {
  if (type & CL_DEVICE_TYPE_GPU) return "GPU";
  if (type & CL_DEVICE_TYPE_CPU) return "CPU";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

std::string trimmed(std::string text) {
  // Some drivers pad names with spaces or a trailing NUL.
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
  return text;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

}  // namespace

std::vector<DeviceDescription> list_devices() {
  // Before the runtime is loaded: some environments make it abort or hang.
  if (const auto problem = runtime_environment_problem()) throw UserError(*problem, kNoRuntimeExitCode);
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error& error) {
    throw UserError("no OpenCL platform found: " + kInstallHint, kNoRuntimeExitCode);
  }
  std::vector<DeviceDescription> devices;
  for (std::size_t p = 0; p < platforms.size(); ++p) {
    std::vector<cl::Device> platform_devices;
    try {
      platforms[p].getDevices(CL_DEVICE_TYPE_ALL, &platform_devices);
    } catch (const cl::Error&) {
      continue;  // a platform without devices (CL_DEVICE_NOT_FOUND) is not an error
    }
    for (std::size_t d = 0; d < platform_devices.size(); ++d) {
      const cl::Device& device = platform_devices[d];
      DeviceDescription description;
      description.platform_index = p;
      description.device_index = d;
      description.platform_name = trimmed(platforms[p].getInfo<CL_PLATFORM_NAME>());
      description.name = trimmed(device.getInfo<CL_DEVICE_NAME>());
      description.type = type_name(device.getInfo<CL_DEVICE_TYPE>());
      description.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
      description.global_memory_bytes = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      description.max_allocation_bytes = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
      description.local_memory_bytes = device.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>();
      description.max_work_group_size = device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
      description.opencl_c_version = trimmed(device.getInfo<CL_DEVICE_OPENCL_C_VERSION>());
      description.device = device;
      devices.push_back(std::move(description));
    }
  }
  if (devices.empty()) {
    throw UserError("no OpenCL device found: " + kInstallHint, kNoRuntimeExitCode);
  }
  return devices;
}

DeviceRequest device_request(const std::string& option) {
  if (!option.empty()) return {option, "--device"};
  const char* from_environment = std::getenv("MESHPARTICLES_DEVICE");
  if (from_environment && *from_environment) return {from_environment, "$MESHPARTICLES_DEVICE"};
  return {};
}

std::string DeviceRequest::described() const { return origin + "='" + text + "'"; }

std::optional<DeviceDescription> match_device(const std::vector<DeviceDescription>& devices,
                                              const DeviceRequest& request) {
  if (request.text.empty()) {
    const auto gpu = std::find_if(devices.begin(), devices.end(), [](const auto& d) { return d.is_gpu(); });
    return gpu != devices.end() ? *gpu : devices.front();
  }
  for (const auto& d : devices) {
    if (d.index() == request.text) return d;
  }
  const std::string needle = lowercase(request.text);
  for (const auto& d : devices) {
    if (lowercase(d.name).find(needle) != std::string::npos ||
        lowercase(d.platform_name).find(needle) != std::string::npos) {
      return d;
    }
  }
  return std::nullopt;
}

DeviceDescription select_device(const std::string& option) {
  const DeviceRequest request = device_request(option);
  if (auto device = match_device(list_devices(), request)) return *device;
  throw UserError("no OpenCL device matches " + request.described() +
                  " (give P:D or part of a device or platform name; `meshparticles devices` lists them)");
}

}  // namespace meshparticles
