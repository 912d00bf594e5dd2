#pragma once
// The template moved smoothly onto a shape before its particles are carried
// over: after the rigid fit, nearest points alone cannot follow a shape that
// is longer, or bulges more, than the template (particles crowd where it
// bulges out and leave holes where it bulges in). A non-rigid closest-point
// fit moves every template vertex by a displacement field that is smoothed
// over the template's surface, first heavily (the whole shape stretched),
// then less (its parts), so particle i keeps its place relative to the
// shape's parts instead of jumping to the nearest surface.
#include <string>

#include "mesh/surface_mesh.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// How `correspond` moves the template onto each shape: this smoothed
// displacement (the default), or the deformation graph
// (correspondence/deformation_graph), which can follow a joint.
enum class TemplateDeformation { smooth, graph };
// "smooth" / "graph": `--deformation`'s words and summary.json's.
std::string deformation_name(TemplateDeformation deformation);

// `template_points`: the template's vertices (ids as in `template_mesh`),
// `shape_points`: the shape's vertices, both in the common frame. Returns the
// template's vertices moved onto the shape, in the common frame.
PointSet deform_template(const SurfaceMesh& template_mesh, const PointSet& template_points, const PointSet& shape_points);

}  // namespace meshparticles
