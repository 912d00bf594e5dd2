#pragma once
// The precomputed geometry of fast marching's triangle updates.
//
// An update computes C's distance from two accepted vertices X and Y. Its
// geometry is a planar frame with X at the origin, Y at (length_xy, 0) and C
// at (c_x, c_y), c_y < 0. Updates are listed under X, the vertex whose
// acceptance triggers them:
// - every triangle (X, A, B) appears once under each corner X, with the
//   frames to update B from (X, A) and A from (X, B);
// - a corner C with an obtuse angle also gets "virtual" updates (Kimmel &
//   Sethian): neighbouring triangles are unfolded into C's plane until a
//   vertex D falls inside C's angle, splitting it into two acute ones,
//   (C; A, D) and (C; D, B).
#include <cstdint>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct PlanarFrame {
  float length_xy;
  float c_x, c_y;
};

struct TriangleAtVertex {
  VertexId a, b;
  PlanarFrame b_from_a;  // C = B, Y = A
  PlanarFrame a_from_b;  // C = A, Y = B
};

struct VirtualUpdate {
  VertexId target;  // C
  VertexId other;   // Y
  PlanarFrame frame;
};

struct TriangleStencils {
  // Both in CSR form by trigger vertex X.
  std::vector<std::uint32_t> triangle_offsets;
  std::vector<TriangleAtVertex> triangles;
  std::vector<std::uint32_t> virtual_offsets;
  std::vector<VirtualUpdate> virtual_updates;
};

// On at most `threads` threads; the same stencils for any number of them.
TriangleStencils build_triangle_stencils(const SurfaceMesh& mesh, unsigned threads = 1);

}  // namespace meshparticles
