#include "reports/paraview_export.hpp"

#include <cmath>
#include <cstdio>

#include "common/atomic_file.hpp"

namespace meshparticles {

void write_particles_ply(const std::filesystem::path& file, std::span<const Vec3> points,
                         std::span<const VertexId> input_vertices) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment meshparticles particles\nelement vertex " << points.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty int particle\nproperty int vertex\n"
           "end_header\n";
    char line[128];
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3& p = points[i];
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g %zu %u\n", p.x, p.y, p.z, i, unsigned(input_vertices[i]));
      out << line;
    }
  });
}

void write_mesh_field_vtk(const std::filesystem::path& file, const SurfaceMesh& mesh, std::span<const float> values,
                          const std::string& name) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "# vtk DataFile Version 3.0\nmeshparticles: " << name << "\nASCII\nDATASET POLYDATA\nPOINTS "
        << mesh.vertex_count() << " float\n";
    char line[128];
    for (const Vec3& p : mesh.positions()) {
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
      out << line;
    }
    out << "POLYGONS " << mesh.triangle_count() << " " << 4 * mesh.triangle_count() << "\n";
    for (const Triangle& t : mesh.triangles()) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    out << "POINT_DATA " << mesh.vertex_count() << "\nSCALARS " << name << " float 1\nLOOKUP_TABLE default\n";
    for (const float value : values) {
      std::snprintf(line, sizeof line, "%.7g\n", std::isinf(value) ? -1.0 : double(value));
      out << line;
    }
  });
}

}  // namespace meshparticles
