#include "reports/run_outputs.hpp"

#include <array>
#include <cstdio>
#include <functional>

#include "common/atomic_directory.hpp"
#include "common/atomic_file.hpp"
#include "common/exact_number.hpp"
#include "common/parallel_for.hpp"
#include "common/worker_threads.hpp"
#include "reports/output_digests.hpp"
#include "reports/paraview_export.hpp"
#include "reports/particle_locations.hpp"

namespace meshparticles {

namespace {

// Coordinates in their shortest exact form: `quality` of the file reads the run's own points.
void write_points(std::ostream& out, const std::vector<ParticleLocation>& locations) {
  for (const ParticleLocation& location : locations) {
    out << exact_triple(location.at.x, location.at.y, location.at.z) << "\n";
  }
}

void write_csv(std::ostream& out, const std::vector<ParticleLocation>& locations) {
  out << kParticlesCsvHeader << "\n";
  char line[320];
  for (std::size_t i = 0; i < locations.size(); ++i) {
    const ParticleLocation& l = locations[i];
    std::snprintf(line, sizeof line, ",%u,%u,%u,%.17g,%.17g,%.17g\n", unsigned(l.on_input.corners[0]),
                  unsigned(l.on_input.corners[1]), unsigned(l.on_input.corners[2]), l.on_input.weights[0],
                  l.on_input.weights[1], l.on_input.weights[2]);
    out << i << "," << l.input_vertex << "," << exact_triple(l.at.x, l.at.y, l.at.z, ',') << line;
  }
}

}  // namespace

void prepare_output_directory(const std::filesystem::path& directory) {
  check_replaceable_directory(directory, kRunOutputFiles);
}

void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh, const RunResult& result,
                       const nlohmann::json& report, unsigned threads) {
  threads = cores_or(threads);
  const std::vector<ParticleLocation> locations = particle_locations(mesh, result);
  std::vector<Vec3> points;
  std::vector<VertexId> input_vertices;
  for (const ParticleLocation& location : locations) {
    points.push_back(location.at);
    input_vertices.push_back(location.input_vertex);
  }
  write_directory_atomically(directory, kRunOutputFiles, [&](const std::filesystem::path& staging) {
    // The largest first (on a million vertices the mesh's two files are 0.7 GB).
    const std::array<std::function<void()>, 5> writers = {
        // On the mesh the particles moved on: for spread, the refined input.
        [&] {
          write_mesh_field_vtp(staging / "mesh_distance.vtp", result.particle_mesh(mesh), result.distance_to_nearest,
                               "distance_to_nearest_particle");
        },
        [&] {
          write_mesh_field_vtk(staging / "mesh_distance.vtk", result.particle_mesh(mesh), result.distance_to_nearest,
                               "distance_to_nearest_particle");
        },
        [&] { write_new_file(staging / "particles.csv", [&](std::ostream& out) { write_csv(out, locations); }); },
        [&] {
          write_new_file(staging / "particles.particles", [&](std::ostream& out) { write_points(out, locations); });
        },
        [&] { write_particles_ply(staging / "particles.ply", points, input_vertices); },
    };
    for_each_lowest_failure_first(writers.size(), threads, [&](std::size_t k) { writers[k](); });
    // Last: it records the size and SHA-256 of the files above as they are on disk.
    const std::string report_text = digested_report_text(report, staging, threads);
    write_new_file(staging / "report.json", [&](std::ostream& out) { out << report_text; });
  });
}

}  // namespace meshparticles
