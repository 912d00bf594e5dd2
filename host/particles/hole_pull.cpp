#include "particles/hole_pull.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

HolePull::HolePull(const SurfaceMesh& mesh, double step) {
  const auto& positions = mesh.positions();
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 a = positions[t[0]], ab = positions[t[1]] - a, ac = positions[t[2]] - a;
    const double longest = std::max({norm(ab), norm(ac), norm(ac - ab)});
    const int parts = std::max(1, int(std::ceil(longest / step)));
    const double area = triangle_area(positions[t[0]], positions[t[1]], positions[t[2]]) / double(parts * parts);
    // The parts pointing as the triangle does, then those pointing the other way.
    for (int i = 0; i < parts; ++i) {
      for (int j = 0; i + j < parts; ++j) {
        points_.push_back(a + ((i + 1.0 / 3) / parts) * ab + ((j + 1.0 / 3) / parts) * ac);
        area_.push_back(area);
        if (i + j + 1 < parts) {
          points_.push_back(a + ((i + 2.0 / 3) / parts) * ab + ((j + 2.0 / 3) / parts) * ac);
          area_.push_back(area);
        }
      }
    }
  }
}

std::vector<Vec3> HolePull::pull(const std::vector<Vec3>& particles, double reach, double margin, double cell_area) {
  std::vector<Vec3> pulls(particles.size());
  if (particles.empty()) return pulls;
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  double moved = 0;
  if (at_full_.size() == particles.size()) {
    for (std::size_t i = 0; i < particles.size(); ++i) moved = std::max(moved, distance(particles[i], at_full_[i]));
  }
  const bool full = at_full_.size() != particles.size() || !(moved < margin) || far_from_ != reach - margin;
  if (full) {
    at_full_ = particles;
    far_.clear();
    far_from_ = reach - margin;
  }
  const auto look = [&](std::uint32_t s) {
    const Vec3& point = points_[s];
    const double query[3] = {point.x, point.y, point.z};
    std::uint32_t nearest = 0;
    double squared = 0;
    tree.knnSearch(query, 1, &nearest, &squared);
    const double distance = std::sqrt(squared);
    if (full && distance > far_from_) far_.push_back(s);
    if (distance <= reach) return;
    pulls[nearest] = pulls[nearest] + (area_[s] / cell_area * (1 - reach / distance)) * (point - particles[nearest]);
  };
  if (full) {
    for (std::uint32_t s = 0; s < points_.size(); ++s) look(s);
  } else {
    for (const std::uint32_t s : far_) look(s);
  }
  return pulls;
}

double HolePull::cover(const std::vector<Vec3>& particles) const {
  if (particles.empty()) return 0;
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  double cover = 0;
  for (const Vec3& point : points_) {
    const double query[3] = {point.x, point.y, point.z};
    std::uint32_t nearest = 0;
    double squared = 0;
    tree.knnSearch(query, 1, &nearest, &squared);
    cover = std::max(cover, squared);
  }
  return std::sqrt(cover);
}

}  // namespace meshparticles
