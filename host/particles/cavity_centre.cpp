#include "particles/cavity_centre.hpp"

#include <algorithm>

namespace meshparticles {

CavitySurface::CavitySurface(const SurfaceMesh& mesh, const VertexTriangles& fans) : fans_(fans) {
  positions_.reserve(mesh.vertex_count());
  for (const Vec3& p : mesh.positions()) positions_.push_back(to_vec3d(p));
  corners_.reserve(3 * mesh.triangles().size());
  for (const Triangle& t : mesh.triangles()) corners_.insert(corners_.end(), t.begin(), t.end());
}

cavity_surface CavitySurface::view() const {
  return {positions_.data(), corners_.data(), fans_.offsets.data(), fans_.triangles.data()};
}

void ParticleBalls::set(std::uint32_t k, const ParticleBall& ball) {
  live_ -= size_[k];
  if (entries_.size() + ball.size() > 2 * (live_ + ball.size()) + 4096) {
    // Taken back: the live balls moved up, in particle order.
    std::vector<ball_entry> kept;
    kept.reserve(live_ + ball.size());
    for (std::uint32_t p = 0; p < start_.size(); ++p) {
      if (p == k) continue;
      const std::uint32_t start = std::uint32_t(kept.size());
      kept.insert(kept.end(), entries_.begin() + start_[p], entries_.begin() + start_[p] + size_[p]);
      start_[p] = start;
    }
    entries_.swap(kept);
    ++compactions_;
  }
  start_[k] = std::uint32_t(entries_.size());
  size_[k] = std::uint32_t(ball.size());
  for (const auto& [vertex, d] : ball) entries_.push_back({vertex, d});
  live_ += ball.size();
}

cavity_particles ParticleBalls::view(const std::vector<vec3d>& points) const {
  return {points.data(), entries_.data(), start_.data(), size_.data()};
}

cavity_scratch CavityScratch::fit(const cavity_scratch_size& size) {
  const auto grow = [](auto& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
  };
  grow(triangles, size.triangles);
  grow(bounds, size.triangles);
  grow(triangle_slots, 2 * std::size_t(size.triangle_slots));
  grow(vertex_slots, 2 * std::size_t(size.vertex_slots));
  grow(vertices, size.corners);
  grow(corner_rows, size.corners);
  grow(ways, size.corners);
  grow(nearest, size.corners);
  grow(table, std::size_t(size.sources) * size.corners);
  grow(planar, size.sources);
  grow(near, size.sources);
  return {triangles.data(), bounds.data(),      triangle_slots.data(), vertex_slots.data(), vertices.data(),
          corner_rows.data(), ways.data(),      nearest.data(),        table.data(),        planar.data(),
          near.data()};
}

cavity cavity_of(const Cavity& c) {
  return {c.at.triangle,     to_vec3d(c.at.at),      c.region.data(), unsigned(c.region.size()),
          c.near.data(),     unsigned(c.near.size()), c.further.data(), unsigned(c.further.size())};
}

CavityCentre cavity_centre_found(const cavity_found& found) {
  CavityCentre centre;
  centre.at = {found.triangle, {found.weights[0], found.weights[1], found.weights[2]}, to_vec3(found.at)};
  centre.away = found.away;
  centre.here = found.here;
  return centre;
}

CavityCentre cavity_centre(const CavitySurface& surface, const Cavity& c, const std::vector<vec3d>& points,
                           const ParticleBalls& balls, CavityScratch& scratch) {
  const cavity shared = cavity_of(c);
  const cavity_surface mesh = surface.view();
  const cavity_scratch_size size = cavity_scratch_sizes(mesh, shared);
  return cavity_centre_found(::cavity_centre(mesh, balls.view(points), shared, scratch.fit(size), size));
}

}  // namespace meshparticles
