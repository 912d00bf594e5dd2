#include "particles/hole_pull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

// A full look again once this share of the points had to be looked at.
constexpr std::size_t kLookAgainShare = 8;  // 1/8
// Parts along a triangle's edge at most (a triangle 60 steps long is cut anyway).
constexpr int kMostParts = 60;

}  // namespace

HolePull::HolePull(const SurfaceMesh& mesh, double step) : mesh_(mesh) {
  const auto& positions = mesh.positions();
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 ab = positions[t[1]] - positions[t[0]], ac = positions[t[2]] - positions[t[0]];
    const double longest = std::max({norm(ab), norm(ac), norm(ac - ab)});
    const int parts = std::clamp(int(std::ceil(longest / step)), 1, kMostParts);
    parts_.push_back(std::uint8_t(parts));
    size_ += std::size_t(parts * parts);
  }
}

template <typename Visit>
void HolePull::for_each_point(Visit&& visit) const {
  const auto& positions = mesh_.positions();
  std::uint32_t index = 0;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Triangle& t = mesh_.triangles()[k];
    const Vec3 a = positions[t[0]], ab = positions[t[1]] - a, ac = positions[t[2]] - a;
    const int parts = parts_[k];
    const double area = triangle_area(positions[t[0]], positions[t[1]], positions[t[2]]) / double(parts * parts);
    // The parts pointing as the triangle does, then beside each the one pointing the other way.
    for (int i = 0; i < parts; ++i) {
      for (int j = 0; i + j < parts; ++j) {
        visit(index++, a + ((i + 1.0 / 3) / parts) * ab + ((j + 1.0 / 3) / parts) * ac, area);
        if (i + j + 1 < parts) visit(index++, a + ((i + 2.0 / 3) / parts) * ab + ((j + 2.0 / 3) / parts) * ac, area);
      }
    }
  }
}

std::vector<Vec3> HolePull::pull(const std::vector<Vec3>& particles, double reach, double cell_area) {
  std::vector<Vec3> pulls(particles.size());
  if (particles.empty()) return pulls;
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  const bool full = looked_from_.size() != particles.size();
  std::vector<double> moved(particles.size(), 0.0);
  if (full) {
    nearest_.assign(size_, 0);
    distance_.assign(size_, 0);
  } else {
    for (std::size_t i = 0; i < particles.size(); ++i) moved[i] = distance(particles[i], looked_from_[i]);
  }
  std::size_t looked = 0;
  for_each_point([&](std::uint32_t s, const Vec3& point, double area) {
    // Its nearest particle is no farther than the one nearest at the full look.
    if (!full && double(distance_[s]) + moved[nearest_[s]] <= reach) return;
    ++looked;
    const double query[3] = {point.x, point.y, point.z};
    std::uint32_t nearest = 0;
    double squared = 0;
    tree.knnSearch(query, 1, &nearest, &squared);
    const double away = std::sqrt(squared);
    if (full) {
      nearest_[s] = nearest;
      float rounded = float(away);
      if (double(rounded) < away) rounded = std::nextafter(rounded, std::numeric_limits<float>::infinity());
      distance_[s] = rounded;
    }
    if (away <= reach) return;
    pulls[nearest] = pulls[nearest] + (area / cell_area * (1 - reach / away)) * (point - particles[nearest]);
  });
  if (full) {
    looked_from_ = particles;
  } else if (looked * kLookAgainShare > size_) {
    looked_from_.clear();  // the next call looks at every point from where the particles are then
  }
  return pulls;
}

double HolePull::cover(const std::vector<Vec3>& particles) const {
  if (particles.empty()) return 0;
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  double cover = 0;
  for_each_point([&](std::uint32_t, const Vec3& point, double) {
    const double query[3] = {point.x, point.y, point.z};
    std::uint32_t nearest = 0;
    double squared = 0;
    tree.knnSearch(query, 1, &nearest, &squared);
    cover = std::max(cover, squared);
  });
  return std::sqrt(cover);
}

}  // namespace meshparticles
