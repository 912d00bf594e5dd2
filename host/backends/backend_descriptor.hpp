#pragma once
// Everything the rest of the program knows about one backend, in one place:
// its name and help text, how a run uses it by default, which of the paper's
// rows it stands beside, and how it is made. A device backend adds its
// update kernel: program files, compile-time sizes, local and device memory
// needs. The table of all backends is backend_table.hpp; adding a backend is
// its own files plus one line there.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geodesics/distance_store.hpp"
#include "mesh/surface_mesh.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_backend.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

class DeviceBackend;
struct UpdateKernel;

// What every backend is made from.
struct BackendInputs {
  const SurfaceMesh& mesh;
  const DistanceStore& distances;
  EnergyParams energy;
  WeightFormat weights = WeightFormat::float32;  // field backends
  std::size_t rebuild_every = 0;                 // field backends; 0: never
};

// The paper's rows (Tables 1 and 2) a backend is measured beside in `bench`.
enum class PaperRow { cpu, gpu1_naive, gpu2_tiled };

struct DeviceKernelSpec {
  std::string update_function;             // "tiled_update", in kernels/tiled_update.cl
  std::vector<std::string> program_files;  // every kernel file of the backend's one program
  bool takes_tile = false;                 // TILE_SIZE (--tile)
  bool takes_weight_format = false;        // WEIGHTS_HALF (--weights)
  // Sets the built-in work-group (and tile) size for `kernel.candidate_slots`
  // on a device of `device_type` ("GPU", "CPU", ...: DeviceDescription::type).
  std::function<void(UpdateKernel& kernel, const std::string& device_type)> default_sizes;
  // The particles one work-group updates.
  std::function<std::size_t(const UpdateKernel& kernel)> particles_per_group;
  // The kernel's __local arrays, in bytes (checked before building; the
  // compiled kernel's own figure is checked after).
  std::function<std::size_t(const UpdateKernel& kernel)> local_memory_bytes;
  // Device bytes per entry of the V x V table at the peak of set-up (the
  // field's half table briefly coexists with the float32 distances).
  std::function<std::size_t(const UpdateKernel& kernel)> table_bytes_per_entry;
  std::function<std::unique_ptr<DeviceBackend>(const DeviceDescription& device, const UpdateKernel& kernel,
                                               const BackendInputs& inputs)>
      make;
};

struct BackendDescriptor {
  std::string name;     // --backend NAME
  std::string summary;  // one line for --help and the docs
  bool field_method = false;  // takes --weights and --rebuild-every; its work follows the moves
  bool needs_dense_table = false;  // streams whole rows of the V x V table: no local distances
  Scheme default_scheme = Scheme::sequential;
  PaperRow paper_row = PaperRow::cpu;
  // Host memory beyond the dense distance table, per table entry
  // (serial-field's weight table; none on local distances).
  std::size_t extra_host_bytes_per_entry = 0;
  // Host backends.
  std::function<std::unique_ptr<ParticleBackend>(const BackendInputs& inputs)> make_host;
  // Device backends: their update kernel.
  std::optional<DeviceKernelSpec> device;

  bool on_device() const { return device.has_value(); }
};

// The complete table behind `distances`, for a backend that streams whole
// rows (`backend` names it in the error when there is none).
const DistanceTable& dense_table_for(const DistanceStore& distances, const std::string& backend);

}  // namespace meshparticles
