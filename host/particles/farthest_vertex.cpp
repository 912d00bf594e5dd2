#include "particles/farthest_vertex.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

namespace meshparticles {

FarthestVertex::FarthestVertex(std::span<const float> nearest)
    : nearest_(nearest),
      taken_(nearest.size(), 0),
      leaves_(std::bit_ceil(std::max<std::size_t>((nearest.size() + kBlock - 1) / kBlock, 1))),
      tree_(2 * leaves_, 0) {
  for (std::size_t b = 0; b * kBlock < nearest.size(); ++b) tree_[leaves_ + b] = block_maximum(b);
  for (std::size_t node = leaves_ - 1; node >= 1; --node) tree_[node] = std::max(tree_[2 * node], tree_[2 * node + 1]);
}

std::uint64_t FarthestVertex::key(VertexId v) const {
  if (taken_[v]) return 0;
  std::uint32_t bits;  // non-negative floats order like their bits
  std::memcpy(&bits, &nearest_[v], sizeof bits);
  return (std::uint64_t(bits) << 32) | (0xFFFFFFFFu - v);
}

std::uint64_t FarthestVertex::block_maximum(std::size_t block) const {
  std::uint64_t best = 0;
  const std::size_t end = std::min(nearest_.size(), (block + 1) * kBlock);
  for (std::size_t v = block * kBlock; v < end; ++v) best = std::max(best, key(VertexId(v)));
  return best;
}

void FarthestVertex::refresh_block(std::size_t block) {
  std::size_t node = leaves_ + block;
  tree_[node] = block_maximum(block);
  for (node /= 2; node >= 1; node /= 2) {
    const std::uint64_t above = std::max(tree_[2 * node], tree_[2 * node + 1]);
    if (tree_[node] == above) break;  // nothing above changes either
    tree_[node] = above;
  }
}

void FarthestVertex::take(VertexId v) {
  taken_[v] = 1;
  refresh_block(v / kBlock);
}

void FarthestVertex::release(VertexId v) {
  taken_[v] = 0;
  refresh_block(v / kBlock);
}

void FarthestVertex::changed(std::span<const VertexId> vertices) {
  std::size_t last_block = SIZE_MAX;  // a region lists neighbours together: skip repeats of a block
  for (const VertexId v : vertices) {
    if (v / kBlock == last_block) continue;
    last_block = v / kBlock;
    refresh_block(last_block);
  }
}

void FarthestVertex::lowered(std::span<const VertexId> vertices) {
  for (const VertexId v : vertices) {
    // Keys only drop: a block's maximum changes only if it was v's.
    const std::uint64_t held = tree_[leaves_ + v / kBlock];  // the block's maximum
    if (held != 0 && vertex_of(held) == v) refresh_block(v / kBlock);
  }
}

std::optional<VertexId> FarthestVertex::farthest() const {
  if (tree_[1] == 0) return std::nullopt;
  return vertex_of(tree_[1]);
}

}  // namespace meshparticles
