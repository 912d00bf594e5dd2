#pragma once
// --backend NAME and its options to a ready ParticleBackend, in two steps:
// check_backend refuses what cannot run (unknown names, options the backend
// does not take, sizes and tables the device or the host cannot hold)
// before any distance is computed; make_backend then builds it.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "backends/backend_descriptor.hpp"
#include "backends/field_backend.hpp"
#include "backends/update_kernel.hpp"
#include "opencl/device_discovery.hpp"

namespace meshparticles {

struct BackendRequest {
  // A backend of the table (backend_table.hpp). Empty in a RunRequest: the
  // default, which the run's distance store decides (plan_run).
  std::string name = field_backend().name;
  std::string device;                          // --device (device backends)
  std::optional<std::size_t> work_group_size;  // --wg
  std::optional<std::size_t> tile_size;        // --tile
  std::optional<WeightFormat> weights;         // --weights (field backends)
  std::optional<std::size_t> rebuild_every;    // --rebuild-every (field backends)
  // Where sizes tuned by `sweep --save` are looked up when neither --wg nor
  // --tile is given; none: use the built-in defaults.
  std::optional<std::filesystem::path> tuning_file;
};

struct CheckedBackend {
  const BackendDescriptor* descriptor = nullptr;
  std::optional<DeviceDescription> device;  // device backends
  std::optional<UpdateKernel> kernel;       // the sizes in effect, for the report
  // Where those sizes came from: "--wg/--tile", "tuning file", "built-in default".
  std::string sizes_from;
  std::string sizes_note;       // details: the tuning entry used, or why none was
  bool tuning_refused = false;  // the tuning file was unreadable or its sizes refused: worth a warning
  WeightFormat weights = WeightFormat::float32;  // field backends
  std::size_t rebuild_every = 0;                 // field backends; 0: never

  const std::string& name() const { return descriptor->name; }
};

// The default of --rebuild-every: never, since the fixed-point field does not
// drift (docs/ALGORITHM.md, "The field backend").
inline constexpr std::size_t kDefaultRebuildEvery = 0;

// Throws UserError for an unknown name, options the backend does not take,
// sizes the device refuses, a table the host or the device cannot hold, and
// a backend that needs the dense table when `dense_distances` is false.
// `particles` picks the tuning entry and sizes the per-particle buffers.
CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh, std::size_t particles,
                             bool dense_distances = true);

// Throws UserError for a kernel that does not build or buffers the device refuses.
std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceStore& distances, const EnergyParams& energy);

}  // namespace meshparticles
