#include "backends/backend_factory.hpp"

#include "backends/backend_table.hpp"
#include "backends/device_backend.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "geodesics/memory_guard.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

// Takes the sizes of the tuning entry for this device, kernel and size
// class (or the nearest class) when there is one the device accepts; says in
// `checked` what was used and why.
void apply_tuned_sizes(const std::filesystem::path& file, const DeviceDescription& device, std::size_t particles,
                       UpdateKernel& kernel, CheckedBackend& checked) {
  TuningStore store;
  try {
    store = TuningStore::load(file, device_backend_names());
  } catch (const UserError& error) {
    checked.sizes_note = error.what();
    checked.tuning_refused = true;
    return;
  }
  const std::optional<TunedSizes> tuned = store.find(device.name, kernel.name(), particles);
  if (!tuned) {
    checked.sizes_note = store.file_found() ? "no entry for this device and kernel in " + file.string()
                                            : "no tuning file at " + file.string();
    return;
  }
  if (kernel.spec().takes_tile != (tuned->tile_size > 0)) {
    checked.sizes_note = "the " + kernel.name() + " entry in " + file.string() + " has " +
                         (tuned->tile_size > 0 ? "a tile, which this kernel does not take" : "no tile");
    checked.tuning_refused = true;
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

std::vector<std::string> names_where(bool (*keep)(const BackendDescriptor&)) {
  std::vector<std::string> names;
  for (const BackendDescriptor* backend : backend_table()) {
    if (keep(*backend)) names.push_back(backend->name);
  }
  return names;
}

void check_options_apply(const BackendRequest& request, const BackendDescriptor& backend) {
  if ((request.weights || request.rebuild_every) && !backend.field_method) {
    const auto field = names_where([](const BackendDescriptor& b) { return b.field_method; });
    throw UserError("--weights and --rebuild-every apply to the " + choice_list(field, "and") + " backends, not " +
                    backend.name);
  }
  if ((request.work_group_size || request.tile_size) && !backend.on_device()) {
    throw UserError("--wg and --tile apply to the device backends (" + choice_list(device_backend_names()) +
                    "), not " + backend.name);
  }
  if (request.tile_size && !backend.device->takes_tile) {
    const auto tiled = names_where([](const BackendDescriptor& b) { return b.on_device() && b.device->takes_tile; });
    throw UserError("--tile applies to the " + choice_list(tiled) + " backend only");
  }
}

}  // namespace

const DistanceTable& dense_table_for(const DistanceStore& distances, const std::string& backend) {
  if (const DistanceTable* table = distances.dense_table()) return *table;
  throw UserError("the " + backend + " backend needs the complete distance table");
}

CheckedBackend check_backend(const BackendRequest& request, const SurfaceMesh& mesh, std::size_t particles,
                             bool dense_distances) {
  CheckedBackend checked;
  checked.descriptor = &find_backend(request.name);
  const BackendDescriptor& backend = *checked.descriptor;
  check_options_apply(request, backend);
  checked.weights = request.weights.value_or(WeightFormat::float32);
  checked.rebuild_every = request.rebuild_every.value_or(kDefaultRebuildEvery);
  if (!dense_distances && backend.needs_dense_table) {
    throw UserError("the " + backend.name + " backend streams rows of the dense distance table: use --distances "
                    "dense (if the table fits), or field, serial-field or serial with local distances");
  }
  if (dense_distances) {
    check_table_fits(mesh.vertex_count(), sizeof(float) + backend.extra_host_bytes_per_entry,
                     usable_host_memory_bytes(),
                     backend.extra_host_bytes_per_entry ? "distance and weight tables" : "distance table",
                     usable_host_memory_name(),
                     backend.extra_host_bytes_per_entry
                         ? "; --weights half halves the weight table, and field or serial-field need no table"
                         : "; field or serial-field need no table (--distances local)");
  }
  if (!backend.on_device()) return checked;

  checked.device = select_device(request.device);
  UpdateKernel kernel = default_update_kernel(backend, mesh.max_valence() + 1, checked.device->max_work_group_size,
                                              checked.device->type);
  kernel.weights = checked.weights;
  checked.sizes_from = "built-in default";
  if (request.work_group_size || request.tile_size) {
    if (request.work_group_size) kernel.work_group_size = *request.work_group_size;
    if (request.tile_size) kernel.tile_size = *request.tile_size;
    checked.sizes_from = "--wg/--tile";
    if (backend.device->takes_tile && !(request.work_group_size && request.tile_size)) {
      checked.sizes_note = "the size not given is the built-in default";
    }
  } else if (request.tuning_file) {
    apply_tuned_sizes(*request.tuning_file, *checked.device, particles, kernel, checked);
  }
  check_device_limits(*checked.device, kernel);
  check_device_memory(*checked.device, kernel, mesh.vertex_count(), mesh.edge_count(), particles, dense_distances);
  checked.kernel = kernel;
  return checked;
}

std::unique_ptr<ParticleBackend> make_backend(const CheckedBackend& checked, const SurfaceMesh& mesh,
                                              const DistanceStore& distances, const EnergyParams& energy) {
  const BackendInputs inputs{mesh, distances, energy, checked.weights, checked.rebuild_every};
  if (checked.device) return make_device_backend(*checked.device, *checked.kernel, inputs);
  return checked.descriptor->make_host(inputs);
}

}  // namespace meshparticles
