#pragma once
// Fields over a mesh's vertices, one row per vertex, shared by the fits
// that move a template (template_deformation, deformation_graph) and the
// relief that tells their poses apart (surface_relief).
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// Area-weighted unit normals of `points` with `triangles` (zero where a
// vertex's triangles have no area: such a vertex agrees with no normal).
PointSet vertex_normals(const std::vector<Triangle>& triangles, const PointSet& points);

// The rows of `points` as a mesh's positions: a moved or embedded copy of
// a mesh is SurfaceMesh(positions_of(points), mesh.triangles()).
std::vector<Vec3> positions_of(const PointSet& points);

// Six times the volume a closed mesh at `points` encloses, signed by its
// triangles' winding (outward normals: positive).
double signed_volume(const std::vector<Triangle>& triangles, const PointSet& points);

// Each row replaced by the mean of itself and its one-ring's, `rounds`
// times: like diffusion, it reaches about sqrt(rounds / 2) edges.
void smooth_over(const SurfaceMesh& mesh, PointSet& field, int rounds);

}  // namespace meshparticles
