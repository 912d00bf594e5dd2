#include "mesh/midpoint_refinement.hpp"

#include <algorithm>
#include <unordered_map>

namespace meshparticles {

VertexId SurfacePoint::nearest_corner(const SurfaceMesh& input) const {
  const auto& positions = input.positions();
  Vec3 at{0, 0, 0};
  for (int k = 0; k < 3; ++k) at = at + weights[k] * positions[corners[k]];
  int best = 0;
  for (int k = 1; k < 3; ++k) {
    if (distance(at, positions[corners[k]]) < distance(at, positions[corners[best]])) best = k;
  }
  return corners[best];
}

std::size_t refined_vertex_count(const SurfaceMesh& input, unsigned levels) {
  // Each round adds a vertex per edge; a closed or open triangle mesh has
  // E' = 2E + 3F edges and F' = 4F faces after it.
  std::size_t vertices = input.vertex_count(), edges = input.edge_count(), faces = input.triangle_count();
  for (unsigned level = 0; level < levels; ++level) {
    vertices += edges;
    edges = 2 * edges + 3 * faces;
    faces *= 4;
  }
  return vertices;
}

namespace {

// A triangle of the refined mesh with its corners' weights in the input
// triangle it lies in.
struct Piece {
  Triangle corners;
  std::uint32_t input_triangle;
  std::array<std::array<double, 3>, 3> weights;  // per corner, over the input triangle's corners
};

}  // namespace

RefinedMesh refine_by_midpoints(const SurfaceMesh& input, unsigned levels) {
  const auto& input_triangles = input.triangles();
  std::vector<Vec3> positions = input.positions();
  std::vector<SurfacePoint> on_input(positions.size());
  std::vector<std::uint8_t> placed(positions.size(), 0);
  std::vector<Piece> pieces;
  pieces.reserve(input_triangles.size());
  for (std::uint32_t t = 0; t < input_triangles.size(); ++t) {
    const Triangle& corners = input_triangles[t];
    pieces.push_back({corners, t, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
    for (int k = 0; k < 3; ++k) {
      if (placed[corners[k]]) continue;
      placed[corners[k]] = 1;
      on_input[corners[k]] = {corners, pieces.back().weights[k]};
    }
  }
  for (VertexId v = 0; v < positions.size(); ++v) {  // in no triangle: itself
    if (!placed[v]) on_input[v] = {{v, v, v}, {1, 0, 0}};
  }
  for (unsigned level = 0; level < levels; ++level) {
    std::unordered_map<std::uint64_t, VertexId> midpoint_of_edge;
    midpoint_of_edge.reserve(pieces.size() * 3 / 2 + 1);
    std::vector<Piece> finer;
    finer.reserve(pieces.size() * 4);
    for (const Piece& piece : pieces) {
      const Triangle& corner_ids = input_triangles[piece.input_triangle];
      std::array<VertexId, 3> mid{};
      std::array<std::array<double, 3>, 3> mid_weights{};
      for (int k = 0; k < 3; ++k) {  // the midpoint of the edge opposite corner k
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        for (int c = 0; c < 3; ++c) mid_weights[k][c] = 0.5 * (piece.weights[a][c] + piece.weights[b][c]);
        const VertexId u = std::min(piece.corners[a], piece.corners[b]), w = std::max(piece.corners[a], piece.corners[b]);
        const auto [it, created] = midpoint_of_edge.try_emplace((std::uint64_t(u) << 32) | w, VertexId(positions.size()));
        mid[k] = it->second;
        if (!created) continue;
        // Placed by its weights, so that position and weights agree exactly.
        Vec3 at{0, 0, 0};
        for (int c = 0; c < 3; ++c) at = at + mid_weights[k][c] * input.positions()[corner_ids[c]];
        positions.push_back(at);
        on_input.push_back({corner_ids, mid_weights[k]});
      }
      const auto& [p0, p1, p2] = piece.corners;
      const auto& w = piece.weights;
      // The corner triangles keep the orientation, and so does the middle one.
      finer.push_back({{p0, mid[2], mid[1]}, piece.input_triangle, {w[0], mid_weights[2], mid_weights[1]}});
      finer.push_back({{mid[2], p1, mid[0]}, piece.input_triangle, {mid_weights[2], w[1], mid_weights[0]}});
      finer.push_back({{mid[1], mid[0], p2}, piece.input_triangle, {mid_weights[1], mid_weights[0], w[2]}});
      finer.push_back({{mid[0], mid[1], mid[2]}, piece.input_triangle, {mid_weights[0], mid_weights[1], mid_weights[2]}});
    }
    pieces.swap(finer);
  }
  std::vector<Triangle> triangles(pieces.size());
  std::transform(pieces.begin(), pieces.end(), triangles.begin(), [](const Piece& p) { return p.corners; });
  return {SurfaceMesh(std::move(positions), std::move(triangles)), levels, std::move(on_input)};
}

}  // namespace meshparticles
