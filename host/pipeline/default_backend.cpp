#include "pipeline/default_backend.hpp"

namespace meshparticles {

DefaultBackend default_paper_backend(StoreKind store, std::size_t particles, const DeviceDescription* device) {
  if (store != StoreKind::dense) {
    // The twin solves balls on every core while a device would wait for
    // them; its sequential loop, as ever.
    return {"serial-field", "default: serial-field on local distances", Scheme::sequential};
  }
  if (!device) return {"serial-field", "default: serial-field on the dense table, no usable OpenCL device"};
  // On a CPU device the one-launch iterations beat the twin at every n
  // (PoCL, whole runs).
  if (device->type != "GPU") return {"field", "default: field on the dense table, device " + device->name};
  if (particles >= kGpuPaysFromParticlesDense) {
    return {"field", "default: field on the dense table, the GPU " + device->name + " pays from " +
                         std::to_string(kGpuPaysFromParticlesDense) + " particles"};
  }
  return {"serial-field", "default: serial-field on the dense table, below the " +
                              std::to_string(kGpuPaysFromParticlesDense) + " particles from which the GPU " +
                              device->name + " pays"};
}

}  // namespace meshparticles
