#include "mesh/surface_walk.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include "mesh/nearest_on_triangle.hpp"

namespace meshparticles {

namespace {
// A walk longer than this is a point that left the surface: it stops where it is.
constexpr int kMostSteps = 256;
// The triangles a step remembers having looked at (three corners' fans of
// a usual valence; past it a triangle may be looked at twice, to no effect).
constexpr std::size_t kLooksRemembered = 48;
}  // namespace

SurfaceWalk::SurfaceWalk(const SurfaceMesh& mesh)
    : mesh_(mesh), around_(vertex_triangles(mesh.triangles(), mesh.vertex_count())) {
  const auto& p = mesh.positions();
  normals_.reserve(mesh.triangle_count());
  for (const Triangle& c : mesh.triangles()) {
    const Vec3 n = cross(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]]);
    const double length = norm(n);
    normals_.push_back(length > 0 ? (1.0 / length) * n : Vec3{});
  }
}

SurfaceLocation SurfaceWalk::nearest_on(std::uint32_t triangle, Vec3 target) const {
  const Triangle& c = mesh_.triangles()[triangle];
  const auto& p = mesh_.positions();
  SurfaceLocation location{triangle, nearest_on_triangle(target, p[c[0]], p[c[1]], p[c[2]]), {}};
  location.at = at_weights(location.weights, p[c[0]], p[c[1]], p[c[2]]);
  return location;
}

SurfaceLocation SurfaceWalk::walk(std::uint32_t from, Vec3 target) const {
  SurfaceLocation best = nearest_on(from, target);
  for (int step = 0; step < kMostSteps; ++step) {
    if (best.weights[0] > 0 && best.weights[1] > 0 && best.weights[2] > 0) return best;  // inside its triangle
    double nearest = distance(best.at, target);
    SurfaceLocation next = best;
    // A triangle around two corners is looked at once: the second look
    // could not be strictly nearer (a third of the looks, most of a walk).
    std::array<std::uint32_t, kLooksRemembered> looked;
    std::size_t looked_count = 0;
    for (const VertexId corner : mesh_.triangles()[best.triangle]) {
      for (const std::uint32_t t : around_.around(corner)) {
        if (t == best.triangle) continue;
        if (std::find(looked.begin(), looked.begin() + looked_count, t) != looked.begin() + looked_count) continue;
        if (looked_count < looked.size()) looked[looked_count++] = t;
        const SurfaceLocation candidate = nearest_on(t, target);
        const double d = distance(candidate.at, target);
        if (d < nearest) std::tie(nearest, next) = std::pair(d, candidate);
      }
    }
    if (next.triangle == best.triangle) return best;
    best = next;
  }
  return best;
}

SurfaceLocation SurfaceWalk::at_vertex(VertexId v) const { return walk(first_triangle(v), mesh_.positions()[v]); }

}  // namespace meshparticles
