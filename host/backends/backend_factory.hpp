#pragma once
// --backend serial|naive|tiled to a ready ParticleBackend.
#include <memory>
#include <optional>
#include <string>

#include "backends/update_kernel.hpp"
#include "geodesics/distance_table.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

struct BackendRequest {
  std::string name = "tiled";  // serial, naive, tiled
  std::string device;          // --device (device backends)
  std::optional<std::size_t> work_group_size;  // --wg
  std::optional<std::size_t> tile_size;        // --tile (tiled)
};

// A request checked against the mesh and the device, before the distance
// table is computed: a refused size fails in a second, not after minutes.
struct CheckedBackend {
  std::string name;
  std::optional<DeviceDescription> device;  // device backends
  std::optional<UpdateKernel> kernel;       // the sizes in effect, for the report
};

bool is_device_backend(const std::string& name);

// Throws UserError for an unknown name, sizes given to a backend that has
// none, and sizes the device refuses.
CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh);

// Throws UserError for a table or a kernel the device refuses.
std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceTable& distances, const EnergyParams& energy);

}  // namespace meshparticles
