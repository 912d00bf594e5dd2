#include "backends/backend_factory.hpp"

#include "backends/device_backend.hpp"
#include "backends/serial_backend.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

bool is_device_backend(const std::string& name) { return name == "naive" || name == "tiled"; }

CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh) {
  CheckedBackend checked{request.name, std::nullopt, std::nullopt};
  if (request.name == "serial") {
    if (request.work_group_size || request.tile_size) {
      throw UserError("--wg and --tile apply to the naive and tiled backends, not serial");
    }
    return checked;
  }
  if (!is_device_backend(request.name)) {
    throw UserError("unknown backend '" + request.name + "' (choose serial, naive or tiled)");
  }
  const KernelKind kind = parse_kernel_kind(request.name);
  if (kind == KernelKind::naive && request.tile_size) throw UserError("--tile applies to the tiled backend only");
  checked.device = select_device(request.device);
  UpdateKernel kernel = default_update_kernel(kind, mesh.max_valence() + 1, checked.device->max_work_group_size);
  if (request.work_group_size) kernel.work_group_size = *request.work_group_size;
  if (request.tile_size) kernel.tile_size = *request.tile_size;
  check_device_limits(*checked.device, kernel);
  checked.kernel = kernel;
  return checked;
}

std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceTable& distances, const EnergyParams& energy) {
  if (!checked.device) return std::make_unique<SerialBackend>(mesh, distances, energy);
  return std::make_unique<DeviceBackend>(*checked.device, mesh, distances, energy, *checked.kernel);
}

}  // namespace meshparticles
