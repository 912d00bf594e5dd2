#pragma once
// What stands off a shape's surface at the scale of its small features (a
// bump, a knob, a nose, a hand): each vertex's height over the surface
// smoothed to a twentieth of its size, along the vertex normal. A bend, or a
// limb turned at a joint, moves the surface but hardly changes its relief,
// so two poses that a fit of the whole shape cannot tell apart (a body
// turned half round, front for back) differ in where the relief lands.
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// The smoothing's reach, as a share of the square root of the area: wide
// enough to flatten a bump or a nose, narrow enough to keep a limb. On
// FAUST's poses 0.1 also flattened what tells front from back (the
// template's relief then agreed about as well with a shape turned half
// round); 0.03 left the agreement to the mesh's own noise.
inline constexpr double kReliefScale = 0.05;

// `points`: the mesh's vertices in any frame (ids as the mesh's). The
// heights are in that frame's units.
Eigen::VectorXd surface_relief(const SurfaceMesh& mesh, const PointSet& points);

// What a bend adds to the relief (the outer side's curvature) varies
// slowly; a bump does not. On bent-either, at the true pairs, the relief of
// a shape bent the other way correlates 0.28 to 0.61 with the template's
// and its half turn's 0.46 to 0.57; less its trend over kReliefBand of the
// square root of the area, 0.51 to 0.70 against 0.01 to 0.16.
inline constexpr double kReliefBand = 0.1;

// surface_relief signed so that a bump stands out whichever way the
// triangles are wound, less its own trend over kReliefBand.
Eigen::VectorXd detrended_relief(const SurfaceMesh& mesh, const PointSet& points);

// The correlation of two reliefs over paired vertices: `a(i)` with
// `b(pairs[i])`, i over a's vertices. 0 where either is flat.
double relief_agreement(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::vector<Eigen::Index>& pairs);

}  // namespace meshparticles
