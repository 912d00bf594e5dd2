#include "reports/run_outputs.hpp"

#include <cstdio>

#include "common/atomic_directory.hpp"
#include "common/atomic_file.hpp"
#include "reports/paraview_export.hpp"

namespace meshparticles {

namespace {

void write_points(std::ostream& out, const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  char line[96];
  for (const VertexId v : positions) {
    const Vec3& p = mesh.positions()[v];
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
    out << line;
  }
}

void write_csv(std::ostream& out, const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  out << "particle,vertex,x,y,z\n";
  char line[128];
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = mesh.positions()[positions[i]];
    std::snprintf(line, sizeof line, "%zu,%u,%.9g,%.9g,%.9g\n", i, unsigned(mesh.input_id(positions[i])), p.x, p.y,
                  p.z);
    out << line;
  }
}

}  // namespace

void prepare_output_directory(const std::filesystem::path& directory) {
  check_replaceable_directory(directory, kRunOutputFiles);
}

void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh, const RunResult& result,
                       const nlohmann::json& report) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  write_directory_atomically(directory, kRunOutputFiles, [&](const std::filesystem::path& staging) {
    write_new_file(staging / "particles.particles", [&](std::ostream& out) { write_points(out, mesh, positions); });
    write_new_file(staging / "particles.csv", [&](std::ostream& out) { write_csv(out, mesh, positions); });
    write_particles_ply(staging / "particles.ply", mesh, positions);
    write_mesh_field_vtk(staging / "mesh_distance.vtk", mesh, result.distance_to_nearest,
                         "distance_to_nearest_particle");
    write_new_file(staging / "report.json", [&](std::ostream& out) { out << report.dump(2) << "\n"; });
  });
}

}  // namespace meshparticles
