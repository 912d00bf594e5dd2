// devices(): what `meshparticles devices` lists, one dict per device, with
// the one a run would select marked (device= or $MESHPARTICLES_DEVICE, else
// the first GPU, else the first device).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "opencl/device_discovery.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

py::list describe_devices(const std::string& device) {
  const auto devices = list_devices();  // no runtime or no device: UserError with kNoRuntimeExitCode
  const std::optional<DeviceDescription> chosen = match_device(devices, device_request(device));
  py::list out;
  for (const auto& d : devices) {
    py::dict entry;
    entry["index"] = d.index();
    entry["platform"] = d.platform_name;
    entry["name"] = d.name;
    entry["type"] = d.type;
    entry["compute_units"] = d.compute_units;
    entry["global_memory_bytes"] = d.global_memory_bytes;
    entry["max_allocation_bytes"] = d.max_allocation_bytes;
    entry["local_memory_bytes"] = d.local_memory_bytes;
    entry["max_work_group_size"] = d.max_work_group_size;
    entry["opencl_c_version"] = d.opencl_c_version;
    entry["selected"] = chosen && chosen->index() == d.index();
    out.append(entry);
  }
  return out;
}

}  // namespace

void bind_devices(py::module_& module) {
  module.def("devices", &describe_devices, py::kw_only(), py::arg("device") = "");
}

}  // namespace meshparticles::python
