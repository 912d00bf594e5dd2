#include "particles/particle_file.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/user_error.hpp"

namespace meshparticles {

std::vector<Vec3> read_particle_points(const std::filesystem::path& file) {
  if (std::filesystem::is_directory(file)) throw UserError(file.string() + ": is a directory, not a particle file");
  std::ifstream in(file);
  if (!in) throw UserError(file.string() + ": no such file or not readable");
  std::vector<Vec3> points;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines carry nothing
    std::istringstream fields(line);
    Vec3 p;
    std::string rest;
    if (!(fields >> p.x >> p.y >> p.z) || (fields >> rest)) {
      throw UserError(file.string() + ": line " + std::to_string(number) + " is not three numbers \"x y z\"");
    }
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw UserError(file.string() + ": line " + std::to_string(number) + " has a NaN or infinite coordinate");
    }
    points.push_back(p);
  }
  if (points.empty()) throw UserError(file.string() + ": no particles (expected one \"x y z\" per line)");
  return points;
}

SnappedParticles snap_to_vertices(const SurfaceMesh& mesh, const std::vector<Vec3>& points) {
  SnappedParticles snapped;
  const auto& vertices = mesh.positions();
  for (std::size_t i = 0; i < points.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    VertexId nearest = 0;
    for (VertexId v = 0; v < vertices.size(); ++v) {
      const Vec3 offset = vertices[v] - points[i];
      const double squared = dot(offset, offset);
      if (squared < best) {
        best = squared;
        nearest = v;
      }
    }
    snapped.positions.push_back(nearest);
    if (std::sqrt(best) > snapped.largest_snap) {
      snapped.largest_snap = std::sqrt(best);
      snapped.largest_snap_particle = i;
    }
  }
  return snapped;
}

}  // namespace meshparticles
