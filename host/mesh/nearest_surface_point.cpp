#include "mesh/nearest_surface_point.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/nearest_on_triangle.hpp"

namespace meshparticles {

namespace {
// A walk that ends within this share of the mean edge length of the point
// has found it on the surface: nothing can be nearer by more than rounding.
constexpr double kOnSurface = 1e-9;
}  // namespace

NearestSurfacePoint::NearestSurfacePoint(const SurfaceMesh& mesh)
    : mesh_(mesh),
      walk_(mesh),
      around_(vertex_triangles(mesh.triangles(), mesh.vertex_count())),
      cloud_{mesh.positions()},
      tree_(std::make_unique<PointCloudTree>(3, cloud_)),
      longest_edge_(longest_edge(mesh)) {}

std::optional<SurfaceLocation> NearestSurfacePoint::find(Vec3 p) const {
  if (mesh_.triangle_count() == 0) return std::nullopt;
  const double query[3] = {p.x, p.y, p.z};
  std::uint32_t nearest_vertex = 0;
  double squared = 0;
  tree_->knnSearch(query, 1, &nearest_vertex, &squared);
  SurfaceLocation best = walk_.walk(walk_.first_triangle(nearest_vertex), p);
  double best_distance = distance(best.at, p);
  if (best_distance <= kOnSurface * mesh_.mean_edge_length()) return best;
  // Every triangle with a corner within reach, each once.
  const double reach = best_distance + longest_edge_;
  std::vector<std::pair<std::uint32_t, double>> near;
  tree_->radiusSearch(query, reach * reach, near, nanoflann::SearchParams(32, 0.0f, false));
  std::vector<std::uint32_t> candidates;
  for (const auto& [v, d2] : near) {
    const auto triangles = around_.around(v);
    candidates.insert(candidates.end(), triangles.begin(), triangles.end());
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  const auto& x = mesh_.positions();
  for (const std::uint32_t t : candidates) {
    const Triangle& c = mesh_.triangles()[t];
    SurfaceLocation location{t, nearest_on_triangle(p, x[c[0]], x[c[1]], x[c[2]]), {}};
    location.at = at_weights(location.weights, x[c[0]], x[c[1]], x[c[2]]);
    const double d = distance(location.at, p);
    if (d < best_distance) std::tie(best, best_distance) = std::pair(location, d);
  }
  return best;
}

}  // namespace meshparticles
