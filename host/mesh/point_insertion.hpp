#pragma once
// Points of a surface made vertices of it: a point splits the triangle it
// lies in into three, or, near an edge, each triangle of that edge into two,
// or, near a corner, is that corner. Spread's particles end between the
// working mesh's vertices; inserted, they are vertices again, so measuring
// them (fast marching from vertices) and writing them (the input triangle
// and weights of each vertex) need nothing new and snap nothing.
#include <array>
#include <cstdint>
#include <vector>

#include "mesh/midpoint_refinement.hpp"
#include "mesh/surface_location.hpp"

namespace meshparticles {

// A point within this barycentric weight of an edge is moved onto the edge
// (and within it of a corner, or, once on the edge, within this share of
// the edge of a corner, onto the corner: inserting the inserted points
// again then gives the same vertices): no triangle thinner than
// this share of its height is made, and a point moves by at most this share
// of its triangle's height (the working mesh's triangles are under half a
// spacing, so under 1% of a spacing).
inline constexpr double kInsertionSnap = 0.02;

struct InsertedPoints {
  RefinedMesh refined;             // the points as vertices; on_input for every vertex
  std::vector<VertexId> vertices;  // per point, in order
};

// `points` lie on triangles of `mesh.mesh`, which refines `input` (their
// triangles and weights are read). The mesh's vertices keep their ids; new
// vertices follow, one per point that is not a corner. Two points at one
// place give one vertex. Each new vertex's on_input is the input triangle
// holding it, with its weights.
InsertedPoints insert_points(const RefinedMesh& mesh, const SurfaceMesh& input,
                             const std::vector<SurfaceLocation>& points, double snap = kInsertionSnap);

}  // namespace meshparticles
