#pragma once
// The ellipsoid a surface mostly lies on, where it does: a quadric fitted to
// the vertices by least squares, the vertices far off it (a bump, a knob)
// dropped and the fit repeated. Its axes say how a shape is turned far
// better than the moments do, which a bump tilts by its own height (3 to 18
// degrees on generated shapes, the fitted axes within half a degree).
#include <optional>

#include "mesh/surface_mesh.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

struct EllipsoidBody {
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes;  // rows: unit axes, longest first, a proper turn
  Eigen::Vector3d radii;  // along those axes
  // Points taken to the body's unit sphere (centred, turned onto its axes,
  // each axis divided by its radius): there shapes whose radii differ
  // differ only by their features.
  PointSet to_unit_sphere(const PointSet& points) const;
};

// None where the surface is not mostly an ellipsoid (its vertices' median
// distance from the fitted quadric over 1% of its size, or the quadric not
// an ellipsoid): a body of many parts, or a shape whose features are as
// large as it is.
std::optional<EllipsoidBody> ellipsoid_body(const PointSet& vertices);

}  // namespace meshparticles
