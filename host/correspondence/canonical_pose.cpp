#include "correspondence/canonical_pose.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "correspondence/surface_relief.hpp"
#include "correspondence/vertex_fields.hpp"
#include "geodesics/solver_factory.hpp"
#include "particles/initial_placement.hpp"

namespace meshparticles {

namespace {

// A rigid fit of `moving` onto the tree's points (iterative closest points,
// each step the Kabsch motion onto the nearest points), from `rotation`.
struct RigidFit {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rms = 0;
};

RigidFit canonical_fit(const PointSet& moving, const PointSet& target, const PointsTree& tree,
                       const Eigen::Matrix3d& rotation, std::size_t iterations) {
  RigidFit fit{rotation};
  PointSet matched(moving.rows(), 3);
  const Eigen::RowVector3d from = moving.colwise().mean();
  const PointSet centred = moving.rowwise() - from;
  for (std::size_t iteration = 0;; ++iteration) {
    const PointSet current = (moving * fit.rotation.transpose()).rowwise() + fit.translation.transpose();
    double squared = 0;
    for (Eigen::Index i = 0; i < current.rows(); ++i) {
      matched.row(i) = target.row(tree.nearest(current.row(i)).front());
      squared += (matched.row(i) - current.row(i)).squaredNorm();
    }
    fit.rms = std::sqrt(squared / double(std::max<Eigen::Index>(1, current.rows())));
    if (iteration == iterations) break;
    const Eigen::RowVector3d to = matched.colwise().mean();
    fit.rotation = best_rotation(centred, matched.rowwise() - to);
    fit.translation = to.transpose() - fit.rotation * from.transpose();
  }
  return fit;
}

}  // namespace

std::optional<PointSet> canonical_form(const SurfaceMesh& mesh, const CanonicalPoseOptions& options) {
  const std::size_t vertices = mesh.vertex_count();
  const std::size_t count = std::min(options.landmarks, vertices);
  if (count < 4) return std::nullopt;
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  PlacementRequest placement;
  placement.init = Init::farthest;
  placement.particle_count = count;
  placement.start_vertex = 0;
  const std::vector<VertexId> landmarks = place_particles(mesh, *solver, placement);
  // Squared geodesic distances at unit area: row l from landmark l to every vertex.
  const double unit_squared = 1.0 / mesh.area();
  const Eigen::Index marks = Eigen::Index(count);
  Eigen::MatrixXd squared(marks, Eigen::Index(vertices));
  SolverScratch scratch;
  scratch.fit(vertices);
  std::vector<double> field(vertices);
  for (std::size_t l = 0; l < count; ++l) {
    solver->solve(landmarks[l], field, scratch);
    for (std::size_t v = 0; v < vertices; ++v) {
      if (!std::isfinite(field[v])) return std::nullopt;  // another component
      squared(Eigen::Index(l), Eigen::Index(v)) = field[v] * field[v] * unit_squared;
    }
  }
  // Classical scaling of the landmarks: B = -1/2 J D J, its three largest
  // eigenpairs (the distances between landmarks made symmetric: a march
  // measures each pair twice, slightly apart).
  Eigen::MatrixXd between(marks, marks);
  for (Eigen::Index a = 0; a < marks; ++a) {
    for (Eigen::Index b = 0; b < marks; ++b) between(a, b) = squared(a, Eigen::Index(landmarks[std::size_t(b)]));
  }
  between = 0.5 * (between + between.transpose()).eval();
  const Eigen::VectorXd mean_squared = between.rowwise().mean();
  const Eigen::MatrixXd centring =
      (Eigen::MatrixXd::Identity(marks, marks).array() - 1.0 / double(count)).matrix();
  const Eigen::MatrixXd gram = -0.5 * centring * between * centring;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  // Every vertex from its squared distances to the landmarks:
  // y_k = -1/2 v_k^T (d - mean) / sqrt(lambda_k).
  Eigen::Matrix<double, 3, Eigen::Dynamic> project(3, marks);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Index column = marks - 1 - k;
    const double lambda = eigen.eigenvalues()(column);
    if (!(lambda > 0)) return std::nullopt;
    project.row(k) = -0.5 * eigen.eigenvectors().col(column).transpose() / std::sqrt(lambda);
  }
  PointSet form = (project * (squared.colwise() - mean_squared)).transpose();
  // The mirror image the scaling may return is not the shape's: its
  // triangles must enclose the form the way they enclose the mesh.
  const PointSet own = vertex_points(mesh);
  if ((signed_volume(mesh.triangles(), form) < 0) != (signed_volume(mesh.triangles(), own) < 0)) {
    form.col(2) = -form.col(2);
  }
  const Similarity frame = canonical_frame(SurfaceMesh(positions_of(form), mesh.triangles()));
  form = frame.apply(form);
  if (options.straighten) {
    // What bend the form keeps (a bend that stretched the surface's outer
    // side): its across coordinates' quadratic trend along the long axis,
    // taken out.
    Eigen::MatrixXd basis(form.rows(), 3);
    basis.col(0).setOnes();
    basis.col(1) = form.col(0);
    basis.col(2) = form.col(0).array().square();
    const Eigen::MatrixXd trend = basis.colPivHouseholderQr().solve(form.rightCols(2));
    form.col(1) -= basis.col(2) * trend(2, 0);
    form.col(2) -= basis.col(2) * trend(2, 1);
    form = canonical_frame(SurfaceMesh(positions_of(form), mesh.triangles())).apply(form);
  }
  return form;
}

CanonicalTemplate::CanonicalTemplate(const SurfaceMesh& template_mesh, const PointSet& template_points,
                                     const PoseChoiceOptions& pose_options)
    : mesh(template_mesh),
      points(template_points),
      form(canonical_form(template_mesh, pose_options.canonical)),
      relief(detrended_relief(template_mesh, template_points)),
      options(pose_options) {}

std::optional<CanonicalPose> choose_pose_canonically(const CanonicalTemplate& reference, const SurfaceMesh& mesh) {
  const CanonicalPoseOptions& options = reference.options.canonical;
  if (!reference.form) return std::nullopt;
  const std::optional<PointSet> form = canonical_form(mesh, options);
  if (!form) return std::nullopt;
  const PointSet& template_form = *reference.form;
  const PointsTree template_tree(template_form);
  const PointSet moving = strided_rows(*form, options.fit_points);

  // Every start: a cube rotation, after a roll about the long axis.
  std::vector<RigidFit> fits;
  const int rolls = std::max(1, int(std::lround(90 / options.roll_degrees)));
  for (int roll = 0; roll < rolls; ++roll) {
    const Eigen::Matrix3d rolled =
        Eigen::AngleAxisd(roll * options.roll_degrees * std::numbers::pi / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
    for (const Eigen::Matrix3d& turn : cube_rotations()) {
      fits.push_back(canonical_fit(moving, template_form, template_tree, turn * rolled, options.fit_iterations));
    }
  }
  // The distinct ends within open_ratio of the best, least rms first (two
  // fits whose rotations differ by less than same_pose_degrees end in one pose).
  std::vector<double> rms;
  std::vector<Eigen::Matrix3d> turns;
  for (const RigidFit& fit : fits) {
    rms.push_back(fit.rms);
    turns.push_back(fit.rotation);
  }
  const std::vector<std::size_t> open =
      distinct_poses(rms, turns, {}, options.open_ratio, reference.options.same_pose_degrees);
  // Each told by where the template's relief lands on the shape's.
  const PointSet own = vertex_points(mesh);
  const Eigen::VectorXd relief = detrended_relief(mesh, own);
  std::vector<double> agreements;
  std::vector<std::vector<Eigen::Index>> pairings;
  for (const std::size_t k : open) {
    const PointSet placed = (*form * fits[k].rotation.transpose()).rowwise() + fits[k].translation.transpose();
    const PointsTree tree(placed);
    std::vector<Eigen::Index>& pairs = pairings.emplace_back(std::size_t(template_form.rows()));
    for (Eigen::Index v = 0; v < template_form.rows(); ++v) pairs[std::size_t(v)] = tree.nearest(template_form.row(v)).front();
    agreements.push_back(relief_agreement(reference.relief, relief, pairs));
  }
  std::vector<Eigen::Matrix3d> open_turns;
  for (const std::size_t k : open) open_turns.push_back(fits[k].rotation);
  CanonicalPose pose;
  MeshAlignment::Relief& told = pose.alignment.relief;
  const std::size_t chosen =
      choose_by_agreement(agreements, open_turns, [](std::size_t c, std::size_t best) { return c == best; }, told);
  told.canonical = true;
  pose.pairs = std::move(pairings[chosen]);

  // The pose in the shape's own space: the rigid motion, at unit area, that
  // lays each template vertex's partner over it.
  const double scale = 1 / std::sqrt(mesh.area());
  PointSet partners(reference.points.rows(), 3);
  for (Eigen::Index v = 0; v < partners.rows(); ++v) partners.row(v) = scale * own.row(pose.pairs[std::size_t(v)]);
  const Eigen::RowVector3d from = partners.colwise().mean(), to = reference.points.colwise().mean();
  Similarity& to_common = pose.alignment.to_common;
  to_common.scale = scale;
  to_common.rotation = best_rotation(partners.rowwise() - from, reference.points.rowwise() - to);
  to_common.translation = to.transpose() - to_common.rotation * from.transpose();
  pose.alignment.rms = std::sqrt(
      mean_squared_to_nearest(to_common.apply(alignment_points(mesh)), reference.points, PointsTree(reference.points)));
  pose.alignment.from_principal_axes = true;
  return pose;
}

}  // namespace meshparticles
