#include "mesh/point_insertion.hpp"

#include <algorithm>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "mesh/nearest_on_triangle.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

namespace {

std::uint64_t edge_key(VertexId a, VertexId b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

class Inserter {
 public:
  Inserter(const RefinedMesh& mesh, const SurfaceMesh& input)
      : input_(input),
        input_around_(vertex_triangles(input.triangles(), input.vertex_count())),
        original_(mesh.mesh.triangles()),
        original_around_(vertex_triangles(original_, mesh.mesh.vertex_count())),
        positions_(mesh.mesh.positions()),
        triangles_(mesh.mesh.triangles()),
        on_input_(mesh.on_input),
        origin_(triangles_.size()) {
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) origin_[t] = t;
  }

  VertexId insert(const SurfaceLocation& point, double snap) {
    const Triangle& first = original_[point.triangle];
    const Vec3 x = at_weights(point.weights, positions_[first[0]], positions_[first[1]], positions_[first[2]]);
    // The piece of the original triangle that holds x now.
    std::uint32_t piece = point.triangle;
    std::array<double, 3> weights = weights_in(piece, x);
    if (const auto found = pieces_.find(point.triangle); found != pieces_.end()) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const std::uint32_t candidate : found->second) {
        const std::array<double, 3> w = weights_in(candidate, x);
        const double d = distance(x, at(candidate, w));
        if (d < nearest) std::tie(nearest, piece, weights) = std::tuple(d, candidate, w);
      }
    }
    const Triangle corners = triangles_[piece];
    const auto largest = std::max_element(weights.begin(), weights.end()) - weights.begin();
    if (weights[largest] >= 1 - snap) return corners[largest];
    const auto smallest = std::min_element(weights.begin(), weights.end()) - weights.begin();
    if (weights[smallest] <= snap) {
      const VertexId a = corners[(smallest + 1) % 3], b = corners[(smallest + 2) % 3];
      const double along = weights[(smallest + 2) % 3] / (weights[(smallest + 1) % 3] + weights[(smallest + 2) % 3]);
      // Moved onto the edge, within `snap` of a corner along it: that corner.
      // Else the point on the edge, inserted again (`quality` of a run's
      // own particles), would be taken for the corner: the run's vertex and
      // the file's measure would differ.
      if (along <= snap) return a;
      if (along >= 1 - snap) return b;
      return split_edge(a, b, along);
    }
    return split_triangle(piece, weights);
  }

  RefinedMesh finish(unsigned levels) {
    return {SurfaceMesh(std::move(positions_), std::move(triangles_)), levels, std::move(on_input_)};
  }

 private:
  std::array<double, 3> weights_in(std::uint32_t t, Vec3 x) const {
    const Triangle& c = triangles_[t];
    return nearest_on_triangle(x, positions_[c[0]], positions_[c[1]], positions_[c[2]]);
  }
  Vec3 at(std::uint32_t t, const std::array<double, 3>& w) const {
    const Triangle& c = triangles_[t];
    return at_weights(w, positions_[c[0]], positions_[c[1]], positions_[c[2]]);
  }

  VertexId new_vertex(const std::array<VertexId, 3>& corners, const std::array<double, 3>& weights) {
    positions_.push_back(at_weights(weights, positions_[corners[0]], positions_[corners[1]], positions_[corners[2]]));
    on_input_.push_back(on_input(corners, weights));
    return VertexId(positions_.size() - 1);
  }

  // The new vertex as a point of the input: its corners' input points,
  // weighted, in the input triangle that holds them all (each working
  // triangle lies in one input triangle).
  SurfaceLocation on_input(const std::array<VertexId, 3>& corners, const std::array<double, 3>& weights) const {
    std::vector<std::pair<VertexId, double>> parts;
    for (int k = 0; k < 3; ++k) {
      const SurfaceLocation& corner = on_input_[corners[k]];
      const Triangle& input_corners = input_.triangles()[corner.triangle];
      for (int j = 0; j < 3; ++j) {
        const double w = weights[k] * corner.weights[j];
        if (w <= 0) continue;
        const auto same = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p.first == input_corners[j]; });
        if (same == parts.end()) parts.emplace_back(input_corners[j], w);
        else same->second += w;
      }
    }
    const auto heaviest = std::max_element(weights.begin(), weights.end()) - weights.begin();
    if (parts.empty() || parts.size() > 3) return on_input_[corners[heaviest]];
    for (const std::uint32_t t : input_around_.around(parts.front().first)) {
      const Triangle& holder = input_.triangles()[t];
      SurfaceLocation point{t, {0, 0, 0}, {}};
      bool holds = true;
      for (const auto& [vertex, w] : parts) {
        const auto k = std::find(holder.begin(), holder.end(), vertex) - holder.begin();
        if (k == 3) {
          holds = false;
          break;
        }
        point.weights[k] = w;
      }
      if (!holds) continue;
      const double total = point.weights[0] + point.weights[1] + point.weights[2];
      for (double& w : point.weights) w /= total;
      const auto& at = input_.positions();
      point.at = at_weights(point.weights, at[holder[0]], at[holder[1]], at[holder[2]]);
      return point;
    }
    return on_input_[corners[heaviest]];  // not reached on a refined mesh
  }

  void add_piece(std::uint32_t of, std::uint32_t piece) {
    auto [entry, created] = pieces_.try_emplace(origin_[of]);
    if (created) entry->second.push_back(origin_[of]);
    entry->second.push_back(piece);
    origin_.push_back(origin_[of]);
  }
  // The triangles holding edge a-b now, in the order of its list. An edge
  // is listed here the first time an insertion reads or changes it, from
  // the mesh's own triangles (in increasing order), which no insertion has
  // changed around it before: the few edges a run's points touch, not the
  // millions of a fine working mesh.
  std::vector<std::uint32_t>& holding(VertexId a, VertexId b) {
    const auto [entry, created] = edges_.try_emplace(edge_key(a, b));
    const auto original_vertices = original_around_.offsets.size() - 1;
    if (created && a < original_vertices && b < original_vertices) {
      for (const std::uint32_t t : original_around_.around(a)) {
        if (std::find(original_[t].begin(), original_[t].end(), b) != original_[t].end()) entry->second.push_back(t);
      }
    }
    return entry->second;
  }
  void replace_on_edge(VertexId a, VertexId b, std::uint32_t old_triangle, std::uint32_t new_triangle) {
    auto& list = holding(a, b);
    std::replace(list.begin(), list.end(), old_triangle, new_triangle);
  }

  VertexId split_edge(VertexId a, VertexId b, double along) {
    const VertexId p = new_vertex({a, b, a}, {1 - along, along, 0});
    const std::vector<std::uint32_t> sharing = std::exchange(holding(a, b), {});  // gone: split
    for (const std::uint32_t s : sharing) {
      const Triangle t = triangles_[s];
      int i = 0;
      while (!((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a))) ++i;
      const VertexId from = t[i], to = t[(i + 1) % 3], opposite = t[(i + 2) % 3];
      const auto added = std::uint32_t(triangles_.size());
      triangles_[s] = {from, p, opposite};
      triangles_.push_back({p, to, opposite});
      add_piece(s, added);
      replace_on_edge(to, opposite, s, added);
      holding(from, p).push_back(s);
      holding(p, to).push_back(added);
      holding(p, opposite).push_back(s);
      holding(p, opposite).push_back(added);
    }
    return p;
  }

  VertexId split_triangle(std::uint32_t u, const std::array<double, 3>& weights) {
    const Triangle t = triangles_[u];
    const VertexId p = new_vertex(t, weights);
    const auto second = std::uint32_t(triangles_.size()), third = second + 1;
    triangles_[u] = {t[0], t[1], p};
    triangles_.push_back({t[1], t[2], p});
    triangles_.push_back({t[2], t[0], p});
    add_piece(u, second);
    add_piece(u, third);
    replace_on_edge(t[1], t[2], u, second);
    replace_on_edge(t[2], t[0], u, third);
    holding(t[0], p) = {u, third};
    holding(t[1], p) = {u, second};
    holding(t[2], p) = {second, third};
    return p;
  }

  const SurfaceMesh& input_;
  const VertexTriangles input_around_;
  const std::vector<Triangle>& original_;
  const VertexTriangles original_around_;
  std::vector<Vec3> positions_;
  std::vector<Triangle> triangles_;
  std::vector<SurfaceLocation> on_input_;
  std::vector<std::uint32_t> origin_;  // per triangle: the triangle of the mesh it is a piece of
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> pieces_;  // split triangles: their pieces
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edges_;   // edges touched: the triangles holding each
};

}  // namespace

InsertedPoints insert_points(const RefinedMesh& mesh, const SurfaceMesh& input, const std::vector<SurfaceLocation>& points,
                             double snap) {
  Inserter inserter(mesh, input);
  std::vector<VertexId> vertices;
  vertices.reserve(points.size());
  for (const SurfaceLocation& point : points) vertices.push_back(inserter.insert(point, snap));
  return {inserter.finish(mesh.levels), std::move(vertices)};
}

}  // namespace meshparticles
