#include "backends/backend_factory.hpp"

#include <algorithm>

#include "backends/device_backend.hpp"
#include "backends/serial_backend.hpp"
#include "backends/serial_field_backend.hpp"
#include "common/user_error.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

// Takes the sizes of the tuning entry for this device, kernel and size
// class (or the nearest class) when there is one the device accepts; says in
// `checked` what was used and why.
void apply_tuned_sizes(const std::filesystem::path& file, const DeviceDescription& device, std::size_t particles,
                       UpdateKernel& kernel, CheckedBackend& checked) {
  std::optional<TunedSizes> tuned;
  try {
    tuned = TuningStore::load(file).find(device.name, kernel.kind, particles);
  } catch (const UserError& error) {
    checked.sizes_note = error.what();
    checked.tuning_refused = true;
    return;
  }
  if (!tuned) {
    checked.sizes_note = "no entry for this device and kernel in " + file.string();
    return;
  }
  UpdateKernel candidate = kernel;
  candidate.work_group_size = tuned->work_group_size;
  candidate.tile_size = tuned->tile_size;
  try {
    check_device_limits(device, candidate);
  } catch (const LimitExceeded& error) {
    checked.sizes_note = "tuned sizes in " + file.string() + " refused: " + error.what();
    checked.tuning_refused = true;
    return;
  }
  kernel = candidate;
  checked.sizes_from = "tuning file";
  checked.sizes_note = file.string() + ", entry " + tuned->size_class + " measured on " + tuned->measured_on;
}

}  // namespace

const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names = {"serial", "serial-field", "naive", "tiled", "field"};
  return names;
}

bool is_device_backend(const std::string& name) { return name == "naive" || name == "tiled" || name == "field"; }

bool is_field_backend(const std::string& name) { return name == "field" || name == "serial-field"; }

CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh, std::size_t particles) {
  CheckedBackend checked;
  checked.name = request.name;
  if (std::find(backend_names().begin(), backend_names().end(), request.name) == backend_names().end()) {
    throw UserError("unknown backend '" + request.name + "' (choose serial, serial-field, naive, tiled or field)");
  }
  if ((request.weights || request.rebuild_every) && !is_field_backend(request.name)) {
    throw UserError("--weights and --rebuild-every apply to the field and serial-field backends, not " + request.name);
  }
  if (request.weights) checked.weights = parse_weight_format(*request.weights);
  checked.rebuild_every = request.rebuild_every.value_or(kDefaultRebuildEvery);
  if (!is_device_backend(request.name)) {
    if (request.work_group_size || request.tile_size) {
      throw UserError("--wg and --tile apply to the device backends (naive, tiled, field), not " + request.name);
    }
    return checked;
  }
  const KernelKind kind = parse_kernel_kind(request.name);
  if (kind != KernelKind::tiled && request.tile_size) throw UserError("--tile applies to the tiled backend only");
  checked.device = select_device(request.device);
  UpdateKernel kernel = default_update_kernel(kind, mesh.max_valence() + 1, checked.device->max_work_group_size);
  kernel.weights = checked.weights;
  checked.sizes_from = "built-in default";
  if (request.work_group_size || request.tile_size) {
    if (request.work_group_size) kernel.work_group_size = *request.work_group_size;
    if (request.tile_size) kernel.tile_size = *request.tile_size;
    checked.sizes_from = "--wg/--tile";
    if (kind == KernelKind::tiled && !(request.work_group_size && request.tile_size)) {
      checked.sizes_note = "the size not given is the built-in default";
    }
  } else if (request.tuning_file) {
    apply_tuned_sizes(*request.tuning_file, *checked.device, particles, kernel, checked);
  }
  check_device_limits(*checked.device, kernel);
  checked.kernel = kernel;
  return checked;
}

std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceTable& distances, const EnergyParams& energy) {
  if (checked.name == "serial-field") {
    return std::make_unique<SerialFieldBackend>(mesh, distances, energy, checked.weights, checked.rebuild_every);
  }
  if (!checked.device) return std::make_unique<SerialBackend>(mesh, distances, energy);
  return make_device_backend(*checked.device, mesh, distances, energy, *checked.kernel, checked.rebuild_every);
}

}  // namespace meshparticles
