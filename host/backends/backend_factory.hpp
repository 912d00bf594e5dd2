#pragma once
// --backend serial|serial-field|naive|tiled|field to a ready ParticleBackend.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "backends/update_kernel.hpp"
#include "geodesics/distance_table.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

struct BackendRequest {
  // field: the fastest, with the same choices as the others (docs/PERFORMANCE.md).
  std::string name = "field";  // serial, serial-field, naive, tiled, field
  std::string device;          // --device (device backends)
  std::optional<std::size_t> work_group_size;  // --wg
  std::optional<std::size_t> tile_size;        // --tile (tiled)
  std::optional<std::string> weights;          // --weights float|half (field backends)
  std::optional<std::size_t> rebuild_every;    // --rebuild-every (field backends)
  // Where sizes tuned by `sweep --save` are looked up when neither --wg nor
  // --tile is given; none: use the built-in defaults.
  std::optional<std::filesystem::path> tuning_file;
};

// A request checked against the mesh and the device, before the distance
// table is computed: a refused size fails in a second, not after minutes.
struct CheckedBackend {
  std::string name;
  std::optional<DeviceDescription> device;  // device backends
  std::optional<UpdateKernel> kernel;       // the sizes in effect, for the report
  // Where those sizes came from: "--wg/--tile", "tuning file", "built-in default".
  std::string sizes_from;
  std::string sizes_note;  // details: the tuning entry used, or why none was
  bool tuning_refused = false;  // the tuning file was unreadable or its sizes refused: worth a warning
  WeightFormat weights = WeightFormat::float32;  // field backends
  std::size_t rebuild_every = 0;                 // field backends; 0: never
};

// The default of --rebuild-every: never, since the fixed-point field does not
// drift (docs/ALGORITHM.md, "The field backend").
inline constexpr std::size_t kDefaultRebuildEvery = 0;

bool is_device_backend(const std::string& name);  // naive, tiled, field
bool is_field_backend(const std::string& name);   // field, serial-field
const std::vector<std::string>& backend_names();

// Throws UserError for an unknown name, sizes given to a backend that has
// none, and sizes the device refuses. `particles` picks the tuning entry.
CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh, std::size_t particles);

// Throws UserError for a table or a kernel the device refuses.
std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceTable& distances, const EnergyParams& energy);

}  // namespace meshparticles
