#include "backends/serial_field_backend.hpp"

#include "backends/local_field_backend.hpp"
#include "geodesics/memory_guard.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

SerialFieldBackend::SerialFieldBackend(const SurfaceMesh& mesh, const DistanceTable& distances,
                                       const EnergyParams& energy, WeightFormat weights, std::size_t rebuild_every)
    : SerialFieldMethod(mesh, rebuild_every), vertex_count_(mesh.vertex_count()) {
  check_table_fits(vertex_count_, sizeof(float), usable_host_memory_bytes(), "weight table", usable_host_memory_name());
  // In float, as the device computes it (particle_energy.h).
  const float inv_two_sigma_sq = float(energy.inv_two_sigma_sq());
  const auto& d = distances.values();
  weights_.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    weights_[i] = stored_weight(weights, pair_weight_float(energy.potential, d[i], inv_two_sigma_sq));
  }
  field_.assign(vertex_count_, 0);
}

void SerialFieldBackend::rebuild_field() {
  std::fill(field_.begin(), field_.end(), 0);
  for (const VertexId p : positions_) {
    const auto row = weight_row(p);
    for (std::size_t v = 0; v < vertex_count_; ++v) field_[v] += field_units(row[v]);
  }
}

void SerialFieldBackend::field_after_move(std::size_t /*c*/, VertexId from, VertexId to) {
  const auto old_row = weight_row(from), new_row = weight_row(to);
  for (std::size_t v = 0; v < vertex_count_; ++v) field_[v] += field_units(new_row[v]) - field_units(old_row[v]);
}

const BackendDescriptor& serial_field_backend() {
  static constexpr const char* kName = "serial-field";
  static const BackendDescriptor descriptor = [] {
    BackendDescriptor d;
    d.name = kName;
    d.summary = "the field method in plain single-threaded C++, every scheme; the twin of field";
    d.field_method = true;
    d.default_scheme = Scheme::sequential;
    d.paper_row = PaperRow::cpu;
    d.extra_host_bytes_per_entry = sizeof(float);  // W beside the distance table
    d.make_host = [](const BackendInputs& inputs) -> std::unique_ptr<ParticleBackend> {
      if (const LocalDistances* balls = inputs.distances.local_balls()) {
        return std::make_unique<LocalFieldBackend>(inputs.mesh, *balls, inputs.energy, inputs.weights,
                                                   inputs.rebuild_every);
      }
      return std::make_unique<SerialFieldBackend>(inputs.mesh, dense_table_for(inputs.distances, kName),
                                                  inputs.energy, inputs.weights, inputs.rebuild_every);
    };
    return d;
  }();
  return descriptor;
}

}  // namespace meshparticles
