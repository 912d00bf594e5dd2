#pragma once
// Shared by the particle-system tests: committed meshes with their distance
// tables, and device backends on the device the suite runs on (PoCL under
// scripts/test.sh, through $MESHPARTICLES_DEVICE).
#include <memory>
#include <string>
#include <vector>

#include "backends/device_backend.hpp"
#include "backends/serial_backend.hpp"
#include "geodesics/distance_table.hpp"
#include "mesh/mesh_reader.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles::testing {

struct MeshWithDistances {
  SurfaceMesh mesh;
  DistanceTable distances;
  explicit MeshWithDistances(const std::string& name)
      : mesh(read(name)), distances(compute_all_pairs(mesh, GeodesicMethod::fast_marching, 0, true)) {}

  EnergyParams default_energy(std::size_t particles, Potential potential = Potential::exp) const {
    return {potential, default_sigma(potential, mesh.area(), particles)};
  }

 private:
  static SurfaceMesh read(const std::string& name) {
    std::vector<std::string> warnings;
    return read_mesh(std::string(MESHES_DIR) + "/" + name, warnings);
  }
};

inline std::unique_ptr<DeviceBackend> device_backend(const MeshWithDistances& m, const EnergyParams& energy,
                                                     KernelKind kind, std::size_t work_group, std::size_t tile = 0,
                                                     WeightFormat weights = WeightFormat::float32) {
  UpdateKernel kernel;
  kernel.kind = kind;
  kernel.work_group_size = work_group;
  kernel.tile_size = tile;
  kernel.candidate_slots = m.mesh.max_valence() + 1;
  kernel.weights = weights;
  return make_device_backend(select_device(""), m.mesh, m.distances, energy, kernel);
}

struct KernelSize {
  KernelKind kind;
  std::size_t work_group;
  std::size_t tile;
};

// Work-group sizes below, at and above one particle's candidates; tiles of
// one, odd, larger than the work-group and larger than n.
inline const std::vector<KernelSize>& kernel_sizes() {
  static const std::vector<KernelSize> sizes = {
      {KernelKind::naive, 1, 0},    {KernelKind::naive, 3, 0},    {KernelKind::naive, 8, 0},
      {KernelKind::naive, 32, 0},   {KernelKind::tiled, 1, 1},    {KernelKind::tiled, 5, 3},
      {KernelKind::tiled, 12, 7},   {KernelKind::tiled, 64, 256}, {KernelKind::tiled, 100, 1000},
      {KernelKind::tiled, 256, 33}, {KernelKind::field, 1, 0},    {KernelKind::field, 7, 0},
      {KernelKind::field, 64, 0},   {KernelKind::field, 256, 0},
  };
  return sizes;
}

inline std::string describe(const KernelSize& size) {
  return kernel_kind_name(size.kind) + " wg " + std::to_string(size.work_group) +
         (size.kind == KernelKind::tiled ? " tile " + std::to_string(size.tile) : "");
}

}  // namespace meshparticles::testing
