#pragma once
// Farthest point sampling's question, answered as the samples come: which
// vertex not yet taken is farthest from every sample so far (ties: the
// smaller id)? In the start the distances only drop, a region at a time, as
// each new sample lowers those nearer to it than to any earlier one; when a
// sample is taken away (farthest-point optimization) its region's rise.
//
// A tree of maxima over blocks of 64 vertices; the answer is its root. A
// lowered vertex that held its block's maximum rescans the block
// (sequential memory) and mends the path above it, which stops where a
// maximum does not change; any other lowered vertex changes nothing. A
// vertex whose distance may have risen always rescans its block.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

class FarthestVertex {
 public:
  // `nearest`: each vertex's distance to the nearest sample (+inf before the
  // first), owned by the caller, who lowers it and reports what it lowered.
  explicit FarthestVertex(std::span<const float> nearest);

  void take(VertexId v);                            // a sample now: never the answer again
  void release(VertexId v);                         // no longer a sample
  void lowered(std::span<const VertexId> vertices);  // their `nearest` dropped
  void changed(std::span<const VertexId> vertices);  // their `nearest` changed either way
  std::optional<VertexId> farthest() const;         // none once every vertex is taken

 private:
  static constexpr std::size_t kBlock = 64;
  // Distance bits above the id's complement: larger is farther, then
  // smaller id; 0 for a taken vertex (no untaken key is 0).
  std::uint64_t key(VertexId v) const;
  static VertexId vertex_of(std::uint64_t key) { return VertexId(0xFFFFFFFFu - (key & 0xFFFFFFFFu)); }
  std::uint64_t block_maximum(std::size_t block) const;  // a scan of the block's keys
  void refresh_block(std::size_t block);                  // its maximum, and the path above

  std::span<const float> nearest_;
  std::vector<std::uint8_t> taken_;
  std::size_t leaves_;               // a power of two, at least the number of blocks
  std::vector<std::uint64_t> tree_;  // tree_[1] the root, tree_[leaves_ + b] block b's maximum
};

}  // namespace meshparticles
