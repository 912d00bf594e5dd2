// correspondence/template_deformation: the template deformed onto a shape
// follows a stretched shape where nearest points cannot, and leaves a
// template on itself where it is.
#include <gtest/gtest.h>

#include "correspondence/mesh_alignment.hpp"
#include "correspondence/template_deformation.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/point_cloud_tree.hpp"

namespace meshparticles::testing {
namespace {

// The template: the committed-style sphere; the shape: another meshing of
// the sphere stretched along x and squeezed along z. The true place of
// template vertex p on the shape is the stretch of p. Deformed, the template
// must land nearer those places than the nearest shape vertices do.
TEST(TemplateDeformation, FollowsAStretchedShapeBetterThanNearestPoints) {
  const SurfaceMesh template_mesh = generate_mesh_at("sphere", 700);
  const SurfaceMesh shape_mesh = generate_mesh_at("sphere", 1000);
  const Eigen::RowVector3d stretch(1.5, 1.0, 0.6);
  const PointSet template_points = vertex_points(template_mesh);
  PointSet shape_points = vertex_points(shape_mesh);
  shape_points.array().rowwise() *= stretch.array();
  PointSet truth = template_points;
  truth.array().rowwise() *= stretch.array();

  const PointSet deformed = deform_template(template_mesh, template_points, shape_points);
  const MatrixRowTree<PointSet> shape_tree(shape_points);
  double nearest_error = 0, deformed_error = 0;
  for (Eigen::Index v = 0; v < template_points.rows(); ++v) {
    nearest_error += (shape_points.row(shape_tree.nearest(template_points.row(v)).front()) - truth.row(v)).norm();
    deformed_error += (deformed.row(v) - truth.row(v)).norm();
  }
  nearest_error /= double(template_points.rows());
  deformed_error /= double(template_points.rows());
  EXPECT_LT(deformed_error, 0.5 * nearest_error) << "deformed " << deformed_error << ", nearest " << nearest_error;
}

TEST(TemplateDeformation, LeavesATemplateOnItselfWhereItIs) {
  const SurfaceMesh mesh = generate_mesh("torus");
  const PointSet points = vertex_points(mesh);
  EXPECT_EQ((deform_template(mesh, points, points) - points).cwiseAbs().maxCoeff(), 0.0);
}


}  // namespace
}  // namespace meshparticles::testing
