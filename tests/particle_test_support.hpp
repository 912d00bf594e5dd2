#pragma once
// Shared by the particle-system tests: committed meshes with their distance
// tables, and device backends on the device the suite runs on (PoCL under
// scripts/test.sh, through $MESHPARTICLES_DEVICE).
#include <memory>
#include <string>
#include <vector>

#include "backends/backend_table.hpp"
#include "backends/device_backend.hpp"
#include "backends/serial_backend.hpp"
#include "geodesics/distance_table.hpp"
#include "geodesics/local_distances.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "particles/particle_params.hpp"
#include "particles/particle_run.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/run_pipeline.hpp"

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

// A quiet local store with balls of `radius`, on `threads` threads (0: all cores).
inline LocalDistances local_store(const SurfaceMesh& mesh, double radius,
                                  std::uint64_t budget = std::uint64_t{1} << 30, unsigned threads = 0) {
  return LocalDistances(mesh, {radius, GeodesicMethod::fast_marching, budget, threads, true, std::nullopt});
}

// The ball radius a run of `particles` takes at `cutoff` hexagonal spacings.
inline double cutoff_radius(const SurfaceMesh& mesh, std::size_t particles, double cutoff = kDefaultCutoff) {
  return cutoff * hexagonal_spacing(mesh.area(), particles);
}

// "torus" for "torus.off": test names from mesh files.
inline std::string mesh_stem(const std::string& file) { return file.substr(0, file.find('.')); }

inline std::unique_ptr<DeviceBackend> device_backend(const MeshWithDistances& m, const EnergyParams& energy,
                                                     const std::string& kind, std::size_t work_group,
                                                     std::size_t tile = 0,
                                                     WeightFormat weights = WeightFormat::float32) {
  UpdateKernel kernel;
  kernel.backend = &find_backend(kind);
  kernel.work_group_size = work_group;
  kernel.tile_size = tile;
  kernel.candidate_slots = m.mesh.max_valence() + 1;
  kernel.weights = weights;
  return make_device_backend(select_device(""), kernel, BackendInputs{m.mesh, m.distances, energy});
}

struct KernelSize {
  std::string kind;  // a device backend
  std::size_t work_group;
  std::size_t tile;
};

// Work-group sizes below, at and above one particle's candidates; tiles of
// one, odd, larger than the work-group and larger than n.
inline const std::vector<KernelSize>& kernel_sizes() {
  static const std::vector<KernelSize> sizes = {
      {"naive", 1, 0},    {"naive", 3, 0},    {"naive", 8, 0},
      {"naive", 32, 0},   {"tiled", 1, 1},    {"tiled", 5, 3},
      {"tiled", 12, 7},   {"tiled", 64, 256}, {"tiled", 100, 1000},
      {"tiled", 256, 33}, {"field", 1, 0},    {"field", 7, 0},
      {"field", 64, 0},   {"field", 256, 0},
  };
  return sizes;
}

inline std::string describe(const KernelSize& size) {
  return size.kind + " wg " + std::to_string(size.work_group) +
         (size.kind == "tiled" ? " tile " + std::to_string(size.tile) : "");
}

// A default run of `particles` on a committed mesh, quiet.
inline RunRequest quiet_run_request(const std::string& name, std::size_t particles) {
  RunRequest request;
  request.mesh_label = name;
  request.particles = particles;
  request.quiet = true;
  return request;
}

// A quiet run of `iterations` with `scheme` from `start`.
inline RunOutcome run(ParticleBackend& backend, const std::vector<VertexId>& start, Scheme scheme, unsigned colors,
                      std::size_t iterations) {
  return run_particles(backend, start, {scheme, colors, iterations, /*quiet=*/true});
}

}  // namespace meshparticles::testing
