#pragma once
// Shapes of a population brought into one frame before their particles are
// matched: each mesh scaled to unit area and centred, then iterative closest
// points onto the template, from the pose as given and from the shape's own
// principal axes (area-weighted second moments, signed by the third moments,
// in each of the four proper sign patterns); the given pose is kept unless
// a principal-axes start fits clearly better. Shapes may arrive in any
// position, size and orientation.
#include <cstddef>
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles {

// A mesh's vertices as a PointSet.
PointSet vertex_points(const SurfaceMesh& mesh);

// Unit area, centroid at 0, principal axes along x, y, z (largest first).
Similarity canonical_frame(const SurfaceMesh& mesh);

struct MeshAlignment {
  Similarity to_common;  // the mesh's coordinates -> the common (template's canonical) frame
  // The root mean square distance from its vertices to the template's
  // nearest, in the common frame (unit area): how well it fits.
  double rms = 0;
  std::size_t iterations = 0;
  bool from_principal_axes = false;  // else from the pose as given
};

// `template_points`: the template's vertices in the common frame, which
// `template_frame` (its canonical_frame) defines.
MeshAlignment align_to_template(const SurfaceMesh& mesh, const PointSet& template_points,
                                const Similarity& template_frame);

}  // namespace meshparticles
