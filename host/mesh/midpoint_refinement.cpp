#include "mesh/midpoint_refinement.hpp"

#include <algorithm>
#include <functional>

#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

std::vector<SurfaceLocation> vertex_locations(const SurfaceMesh& mesh) {
  std::vector<SurfaceLocation> locations(mesh.vertex_count());
  std::vector<std::uint8_t> placed(mesh.vertex_count(), 0);
  const auto& triangles = mesh.triangles();
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const VertexId v = triangles[t][k];
      if (placed[v]) continue;
      placed[v] = 1;
      locations[v] = {t, {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0}, mesh.positions()[v]};
    }
  }
  return locations;
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

using Weights = std::array<double, 3>;  // over an input triangle's corners

// A triangle of the refined mesh with its corners' weights in the input
// triangle it lies in.
struct Piece {
  Triangle corners;
  std::uint32_t input_triangle;
  std::array<Weights, 3> weights;  // per corner
};

// The input cut into pieces, round after round: each round splits the
// edges it is told to at their midpoints, and each piece with one, two or
// three split edges into two, three or four (a conforming mesh, since
// both pieces along an edge see the same decision).
class Refiner {
 public:
  explicit Refiner(const SurfaceMesh& input)
      : input_(input), positions_(input.positions()), on_input_(vertex_locations(input)) {
    const auto& triangles = input.triangles();
    pieces_.reserve(triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
      pieces_.push_back({triangles[t], t, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
    }
  }

  std::size_t vertex_count() const { return positions_.size(); }
  const std::vector<Vec3>& positions() const { return positions_; }

  // The distinct edges of the pieces for which `split` holds.
  std::size_t count_edges(const std::function<bool(VertexId, VertexId)>& split) {
    const std::vector<std::uint32_t>& first = first_slots();
    std::size_t count = 0;
    for (std::uint32_t slot = 0; slot < first.size(); ++slot) {
      if (first[slot] == slot && split(edge_start(slot), edge_end(slot))) ++count;
    }
    return count;
  }

  void split_round(const std::function<bool(VertexId, VertexId)>& split) {
    const std::vector<std::uint32_t>& first = first_slots();
    std::vector<VertexId> midpoint_at(first.size());  // per slot whose edge is split
    std::vector<Piece> finer;
    finer.reserve(pieces_.size() * 4);
    for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
      const Piece& piece = pieces_[i];
      // The midpoint of the edge opposite corner k, if that edge is split.
      std::array<VertexId, 3> mid{};
      std::array<Weights, 3> mid_weights{};
      std::array<bool, 3> cut{};
      for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        cut[k] = split(piece.corners[a], piece.corners[b]);
        if (!cut[k]) continue;
        for (int c = 0; c < 3; ++c) mid_weights[k][c] = 0.5 * (piece.weights[a][c] + piece.weights[b][c]);
        const std::uint32_t slot = 3 * i + k;
        mid[k] = midpoint_at[slot] = first[slot] == slot ? midpoint(piece, mid_weights[k]) : midpoint_at[first[slot]];
      }
      cut_piece(piece, cut, mid, mid_weights, finer);
    }
    pieces_.swap(finer);
    first_slot_.clear();
  }

  RefinedMesh finish(unsigned rounds) {
    std::vector<Triangle> triangles(pieces_.size());
    std::transform(pieces_.begin(), pieces_.end(), triangles.begin(), [](const Piece& p) { return p.corners; });
    return {SurfaceMesh(std::move(positions_), std::move(triangles)), rounds, std::move(on_input_)};
  }

 private:
  // An edge of the pieces is named by a slot, 3 x piece + the corner
  // opposite it. The edge's first slot (the first piece holding it, as
  // pieces are visited in order) decides for it and makes its midpoint.
  VertexId edge_start(std::uint32_t slot) const { return pieces_[slot / 3].corners[(slot % 3 + 1) % 3]; }
  VertexId edge_end(std::uint32_t slot) const { return pieces_[slot / 3].corners[(slot % 3 + 2) % 3]; }

  // Per slot, its edge's first slot: the first piece around one end that
  // holds the other (pieces around a vertex in increasing order), not a map
  // of the millions of edges of a fine mesh.
  const std::vector<std::uint32_t>& first_slots() {
    if (!first_slot_.empty() || pieces_.empty()) return first_slot_;
    std::vector<Triangle> corners(pieces_.size());
    std::transform(pieces_.begin(), pieces_.end(), corners.begin(), [](const Piece& p) { return p.corners; });
    const VertexTriangles around = vertex_triangles(corners, positions_.size());
    first_slot_.resize(3 * pieces_.size());
    for (std::uint32_t slot = 0; slot < first_slot_.size(); ++slot) {
      const VertexId a = edge_start(slot), b = edge_end(slot);
      for (const std::uint32_t t : around.around(a)) {
        const Triangle& c = corners[t];
        const auto at = std::find(c.begin(), c.end(), b) - c.begin();
        if (at == 3) continue;
        // The corner of piece t that is neither end.
        const auto opposite = 3 - at - (std::find(c.begin(), c.end(), a) - c.begin());
        first_slot_[slot] = 3 * t + std::uint32_t(opposite);
        break;
      }
    }
    return first_slot_;
  }

  // A new vertex at `weights` of the input triangle `piece` lies in.
  VertexId midpoint(const Piece& piece, const Weights& weights) {
    // Placed by its weights, so that position and weights agree exactly.
    const Triangle& corners = input_.triangles()[piece.input_triangle];
    Vec3 at{0, 0, 0};
    for (int c = 0; c < 3; ++c) at = at + weights[c] * input_.positions()[corners[c]];
    positions_.push_back(at);
    on_input_.push_back({piece.input_triangle, weights, at});
    return VertexId(positions_.size() - 1);
  }

  // The pieces of `piece` once the edges marked in `cut` are split; every
  // piece keeps the orientation of its parent.
  void cut_piece(const Piece& piece, const std::array<bool, 3>& cut, const std::array<VertexId, 3>& mid,
                 const std::array<Weights, 3>& mid_weights, std::vector<Piece>& out) const {
    const auto& p = piece.corners;
    const auto& w = piece.weights;
    const std::uint32_t t = piece.input_triangle;
    const int count = int(cut[0]) + int(cut[1]) + int(cut[2]);
    if (count == 0) {
      out.push_back(piece);
      return;
    }
    if (count == 3) {
      out.push_back({{p[0], mid[2], mid[1]}, t, {w[0], mid_weights[2], mid_weights[1]}});
      out.push_back({{mid[2], p[1], mid[0]}, t, {mid_weights[2], w[1], mid_weights[0]}});
      out.push_back({{mid[1], mid[0], p[2]}, t, {mid_weights[1], mid_weights[0], w[2]}});
      out.push_back({{mid[0], mid[1], mid[2]}, t, {mid_weights[0], mid_weights[1], mid_weights[2]}});
      return;
    }
    if (count == 1) {  // the midpoint joined to the opposite corner k
      const int k = cut[0] ? 0 : cut[1] ? 1 : 2, a = (k + 1) % 3, b = (k + 2) % 3;
      out.push_back({{p[k], p[a], mid[k]}, t, {w[k], w[a], mid_weights[k]}});
      out.push_back({{p[k], mid[k], p[b]}, t, {w[k], mid_weights[k], w[b]}});
      return;
    }
    // Two: the uncut edge is opposite corner k; its ends a, b. The corner
    // triangle at k, then the quad a, b, mid[a], mid[b] cut along its
    // shorter diagonal (the first on a tie).
    const int k = !cut[0] ? 0 : !cut[1] ? 1 : 2, a = (k + 1) % 3, b = (k + 2) % 3;
    out.push_back({{mid[b], mid[a], p[k]}, t, {mid_weights[b], mid_weights[a], w[k]}});
    const double a_diagonal = distance(positions_[p[a]], positions_[mid[a]]);
    const double b_diagonal = distance(positions_[p[b]], positions_[mid[b]]);
    if (a_diagonal <= b_diagonal) {
      out.push_back({{p[a], p[b], mid[a]}, t, {w[a], w[b], mid_weights[a]}});
      out.push_back({{p[a], mid[a], mid[b]}, t, {w[a], mid_weights[a], mid_weights[b]}});
    } else {
      out.push_back({{p[a], p[b], mid[b]}, t, {w[a], w[b], mid_weights[b]}});
      out.push_back({{p[b], mid[a], mid[b]}, t, {w[b], mid_weights[a], mid_weights[b]}});
    }
  }

  const SurfaceMesh& input_;
  std::vector<Vec3> positions_;
  std::vector<SurfaceLocation> on_input_;
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> first_slot_;  // of pieces_ (empty: not found yet)
};

}  // namespace

RefinedMesh refine_by_midpoints(const SurfaceMesh& input, unsigned levels) {
  Refiner refiner(input);
  for (unsigned level = 0; level < levels; ++level) refiner.split_round([](VertexId, VertexId) { return true; });
  return refiner.finish(levels);
}

RefinedMesh refine_long_edges(const SurfaceMesh& input, double longest, std::size_t max_vertices) {
  return refine_by_midpoints_then_long_edges(input, 0, longest, max_vertices);
}

RefinedMesh refine_by_midpoints_then_long_edges(const SurfaceMesh& input, unsigned levels, double longest,
                                                std::size_t max_vertices) {
  Refiner refiner(input);
  for (unsigned level = 0; level < levels; ++level) refiner.split_round([](VertexId, VertexId) { return true; });
  const auto too_long = [&](VertexId a, VertexId b) {
    return distance(refiner.positions()[a], refiner.positions()[b]) > longest;
  };
  unsigned rounds = levels;
  bool stopped_at_cap = false;
  while (true) {
    const std::size_t splits = refiner.count_edges(too_long);
    stopped_at_cap = splits != 0 && refiner.vertex_count() + splits > max_vertices;
    if (splits == 0 || stopped_at_cap) break;
    refiner.split_round(too_long);
    ++rounds;
  }
  RefinedMesh refined = refiner.finish(rounds);
  refined.stopped_at_cap = stopped_at_cap;
  return refined;
}

}  // namespace meshparticles
