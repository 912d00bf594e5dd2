#include "particles/surface_voronoi_rounds.hpp"

#include <stdexcept>

#include "common/parallel_for.hpp"
#include "common/worker_threads.hpp"

namespace meshparticles {

namespace {

// A round's vertices go to the threads in pieces of this many (a piece is
// some tens of microseconds' work); a round of fewer runs on the calling
// thread.
constexpr std::size_t kRoundPiece = 1024;
// A round whose dirty vertices are more than this share of the mesh's
// (1 / kScanShare) takes them in the order of their ids, by a scan of the
// marks: their stencils then lie in order in memory.
constexpr std::size_t kScanShare = 16;

}  // namespace

std::vector<VertexId> rounds_start_after_moves(const VoronoiStencils& stencils, const MovedPointsReseeded& reseeded,
                                               const SurfaceVoronoi& cells) {
  std::vector<VertexId> changed = reseeded.corners;
  if (reseeded.emptied.empty()) return changed;
  std::vector<char> emptied(cells.owner.size(), 0);
  for (const VertexId v : reseeded.emptied) emptied[v] = 1;
  for (VertexId w = 0; w < cells.owner.size(); ++w) {
    if (cells.owner[w] == SurfaceVoronoi::kNoPoint) continue;
    for (std::uint32_t k = stencils.dependent_offsets[w]; k < stencils.dependent_offsets[w + 1]; ++k) {
      if (!emptied[stencils.dependents[k]]) continue;
      changed.push_back(w);
      break;
    }
  }
  return changed;
}

SurfaceVoronoiRounds::SurfaceVoronoiRounds(const SurfaceMesh& mesh, unsigned threads)
    : mesh_(mesh), threads_(cores_or(threads)), stencils_(voronoi_stencils_of(mesh)) {}

SurfaceVoronoi SurfaceVoronoiRounds::diagram(std::span<const SurfaceLocation> points) {
  std::vector<VertexId> seeds;
  SurfaceVoronoi voronoi = seeded_surface_voronoi(mesh_, points, seeds);
  if (!seeds.empty()) converge(seeds, voronoi);
  ++statistics_.diagrams;
  return voronoi;
}

void SurfaceVoronoiRounds::update(std::span<const SurfaceLocation> points, std::span<const char> moved,
                                  SurfaceVoronoi& cells) {
  const MovedPointsReseeded reseeded = reseed_moved_points(mesh_, points, moved, cells);
  const std::vector<VertexId> changed = rounds_start_after_moves(stencils_, reseeded, cells);
  if (!changed.empty()) converge(changed, cells);
  ++statistics_.diagrams;
}

void SurfaceVoronoiRounds::converge(std::span<const VertexId> changed, SurfaceVoronoi& voronoi) {
  const std::size_t vertices = mesh_.vertex_count();
  states_.resize(vertices);
  for (std::size_t v = 0; v < vertices; ++v) states_[v] = {voronoi.distance[v], voronoi.owner[v], 0, 0};
  dirty_for_.assign(vertices, 0);
  // Round r's dirty vertices, each once: those a vertex changed in round
  // r - 1 is read by (round 0: the vertices in `changed`, stamped 1).
  dirty_.clear();
  const auto mark_dependents = [&](VertexId c, std::uint32_t round, std::vector<VertexId>& dirty) {
    for (std::uint32_t k = stencils_.dependent_offsets[c]; k < stencils_.dependent_offsets[c + 1]; ++k) {
      const VertexId w = stencils_.dependents[k];
      if (dirty_for_[w] == round + 1) continue;
      dirty_for_[w] = round + 1;
      dirty.push_back(w);
    }
  };
  for (const VertexId c : changed) {
    states_[c].stamp = 1;
    mark_dependents(c, 0, dirty_);
  }
  const voronoi_stencils view = stencils_.view(mesh_);
  // Lexicographic (distance, owner) falls at every change, so the rounds
  // end; this bound only guards against a broken stencil.
  const std::size_t most_rounds = 4 * vertices + 64;
  for (std::uint32_t round = 0; !dirty_.empty(); ++round) {
    if (round > most_rounds) throw std::runtime_error("the Voronoi diagram's rounds did not converge");
    // Every dirty vertex's step reads the last round's states only; they
    // are written once all are computed (Jacobi), so neither the threads
    // nor the order change a bit.
    if (dirty_.size() * kScanShare > vertices) {
      dirty_.clear();
      for (VertexId v = 0; v < vertices; ++v) {
        if (dirty_for_[v] == round + 1) dirty_.push_back(v);
      }
    }
    now_.resize(dirty_.size());
    changed_.resize(dirty_.size());
    const auto step = [&](std::size_t, std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        changed_[i] = char(voronoi_vertex_round(view, dirty_[i], round, states_.data(), 1, &now_[i]));
      }
    };
    if (dirty_.size() < kRoundPiece || threads_ == 1) {
      step(0, 0, dirty_.size());
    } else {
      for_each_piece(dirty_.size(), kRoundPiece, threads_, step);
    }
    next_dirty_.clear();
    bool any = false;
    for (std::size_t i = 0; i < dirty_.size(); ++i) {
      if (!changed_[i]) continue;
      any = true;
      states_[dirty_[i]] = now_[i];
      mark_dependents(dirty_[i], round + 1, next_dirty_);
    }
    statistics_.rounds += any;
    dirty_.swap(next_dirty_);
  }
  for (std::size_t v = 0; v < vertices; ++v) {
    voronoi.distance[v] = states_[v].distance;
    voronoi.owner[v] = states_[v].owner;
  }
}

}  // namespace meshparticles
