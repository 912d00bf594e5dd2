#include "correspondence/template_deformation.hpp"

#include <array>

#include "correspondence/vertex_fields.hpp"
#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

// Rounds of one-ring averaging of the displacement per stage, and fits per
// stage: the field is smooth at first (the whole shape follows), finer later.
constexpr std::array<int, 4> kSmoothingRounds = {64, 32, 16, 8};
constexpr int kFitsPerStage = 8;

}  // namespace

std::string deformation_name(TemplateDeformation deformation) {
  switch (deformation) {
    case TemplateDeformation::smooth:
      return "smooth";
    case TemplateDeformation::graph:
      return "graph";
  }
  return {};
}

PointSet deform_template(const SurfaceMesh& template_mesh, const PointSet& template_points, const PointSet& shape_points) {
  PointSet moved = template_points;
  const MatrixRowTree<PointSet> shape_tree(shape_points);
  const Eigen::Index count = moved.rows();
  for (const int rounds : kSmoothingRounds) {
    for (int fit = 0; fit < kFitsPerStage; ++fit) {
      // Both ways: each template vertex towards its nearest shape vertex, and
      // each shape vertex pulls its nearest template vertex (which reaches
      // into a bulge the template lacks).
      PointSet pull = PointSet::Zero(count, 3);
      Eigen::VectorXd pulls = Eigen::VectorXd::Ones(count);
      for (Eigen::Index v = 0; v < count; ++v) {
        pull.row(v) = shape_points.row(shape_tree.nearest(moved.row(v)).front()) - moved.row(v);
      }
      const MatrixRowTree<PointSet> template_tree(moved);
      for (Eigen::Index w = 0; w < shape_points.rows(); ++w) {
        const Eigen::Index v = template_tree.nearest(shape_points.row(w)).front();
        pull.row(v) += shape_points.row(w) - moved.row(v);
        pulls(v) += 1;
      }
      pull.array().colwise() /= pulls.array();
      smooth_over(template_mesh, pull, rounds);
      moved += pull;
    }
  }
  return moved;
}

}  // namespace meshparticles
