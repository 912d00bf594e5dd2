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

std::vector<Vec3> places(const std::vector<SurfaceLocation>& particles) {
  std::vector<Vec3> at;
  at.reserve(particles.size());
  for (const SurfaceLocation& particle : particles) at.push_back(particle.at);
  return at;
}

struct Nearest {
  std::uint32_t particle = 0;
  double away = std::numeric_limits<double>::infinity();
};

// The particle `point` (of `triangle`) belongs to: the straight nearest in
// `tree` (over `at`), unless `regions` bound its distance along the surface
// to every particle to over HolePull::kThroughTheAir times that (for each
// corner c, d(c) - |point - c|); then the straight nearest of the particles
// whose regions hold the corners.
Nearest nearest_on_surface(const SurfaceMesh& mesh, std::uint32_t triangle, const Vec3& point,
                           const PointCloudTree& tree, const std::vector<Vec3>& at, const SurfaceVoronoi& regions) {
  const double query[3] = {point.x, point.y, point.z};
  Nearest straight;
  double squared = 0;
  tree.knnSearch(query, 1, &straight.particle, &squared);
  straight.away = std::sqrt(squared);
  double along = 0;
  Nearest owner;
  for (const VertexId c : mesh.triangles()[triangle]) {
    along = std::max(along, double(regions.distance[c]) - distance(point, mesh.positions()[c]));
    const std::uint32_t q = regions.owner[c];
    if (q == SurfaceVoronoi::kNoPoint) continue;
    const double away = distance(point, at[q]);
    if (away < owner.away || (away == owner.away && q < owner.particle)) owner = {q, away};
  }
  const bool through_the_air = along > HolePull::kThroughTheAir * straight.away && std::isfinite(owner.away);
  return through_the_air ? owner : straight;
}

}  // namespace

HolePull::HolePull(const SurfaceMesh& mesh, const GeodesicSolver& solver, double step)
    : mesh_(mesh), solver_(solver) {
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
        visit(index++, std::uint32_t(k), a + ((i + 1.0 / 3) / parts) * ab + ((j + 1.0 / 3) / parts) * ac, area);
        if (i + j + 1 < parts) visit(index++, std::uint32_t(k), a + ((i + 2.0 / 3) / parts) * ab + ((j + 2.0 / 3) / parts) * ac, area);
      }
    }
  }
}

std::vector<Vec3> HolePull::pull(const std::vector<SurfaceLocation>& particles, double reach, double cell_area,
                                 SolverScratch& scratch) {
  std::vector<Vec3> pulls(particles.size());
  if (particles.empty()) return pulls;
  const std::vector<Vec3> at = places(particles);
  const PointCloud cloud{at};
  const PointCloudTree tree(3, cloud);
  const bool full = looked_from_.size() != particles.size();
  const bool narrow = particles.size() <= std::size_t(std::numeric_limits<std::uint16_t>::max()) + 1;
  std::vector<double> moved(particles.size(), 0.0);
  if (full) {
    regions_ = surface_voronoi(mesh_, solver_, particles, scratch);
    nearest_narrow_.assign(narrow ? size_ : 0, 0);
    nearest_.assign(narrow ? 0 : size_, 0);
    distance_.assign(size_, 0);
  } else {
    for (std::size_t i = 0; i < particles.size(); ++i) moved[i] = distance(at[i], looked_from_[i]);
  }
  std::size_t looked = 0;
  for_each_point([&](std::uint32_t s, std::uint32_t triangle, const Vec3& point, double area) {
    // Its particle is no farther than the one it had at the full look.
    if (!full && double(distance_[s]) + moved[narrow ? nearest_narrow_[s] : nearest_[s]] <= reach) return;
    ++looked;
    const Nearest nearest = nearest_on_surface(mesh_, triangle, point, tree, at, regions_);
    if (full) {
      if (narrow) {
        nearest_narrow_[s] = std::uint16_t(nearest.particle);
      } else {
        nearest_[s] = nearest.particle;
      }
      float rounded = float(nearest.away);
      if (double(rounded) < nearest.away) rounded = std::nextafter(rounded, std::numeric_limits<float>::infinity());
      distance_[s] = rounded;
    }
    if (nearest.away <= reach) return;
    pulls[nearest.particle] =
        pulls[nearest.particle] + (area / cell_area * (1 - reach / nearest.away)) * (point - at[nearest.particle]);
  });
  if (full) {
    looked_from_ = at;
  } else if (looked * kLookAgainShare > size_) {
    looked_from_.clear();  // the next call looks at every point from where the particles are then
  }
  return pulls;
}

double HolePull::cover(const std::vector<SurfaceLocation>& particles) const {
  if (particles.empty()) return 0;
  const std::vector<Vec3> at = places(particles);
  const PointCloud cloud{at};
  const PointCloudTree tree(3, cloud);
  SolverScratch scratch;
  const SurfaceVoronoi regions = surface_voronoi(mesh_, solver_, particles, scratch);
  double cover = 0;
  for_each_point([&](std::uint32_t, std::uint32_t triangle, const Vec3& point, double) {
    cover = std::max(cover, nearest_on_surface(mesh_, triangle, point, tree, at, regions).away);
  });
  return cover;
}

}  // namespace meshparticles
