#pragma once
// The collision rule of one sub-step, as the serial backends apply it
// (docs/ALGORITHM.md, "Collisions"; the devices: kernels/claims.h): movers
// come in index order, the first to choose a vertex moves there and the
// others stay.
#include <cstddef>
#include <span>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Calls move(k) for each winning mover k; returns how many moved.
template <typename Move>
std::size_t commit_in_index_order(std::span<const VertexId> targets, std::size_t vertex_count, Move move) {
  std::vector<bool> taken(vertex_count, false);
  std::size_t moved = 0;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    if (taken[targets[k]]) continue;
    taken[targets[k]] = true;
    move(k);
    ++moved;
  }
  return moved;
}

}  // namespace meshparticles
