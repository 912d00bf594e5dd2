#include "correspondence/mesh_alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

constexpr std::size_t kMaxIterations = 60;
constexpr double kSettled = 1e-9;            // rms change, unit-area units
constexpr Eigen::Index kMaxFitPoints = 4000;  // vertices fitted, evenly strided beyond
// A start from the principal axes replaces the given pose when it fits at
// least this much better (rms ratio) after kTrialIterations.
constexpr double kClearlyBetter = 0.8;
constexpr std::size_t kTrialIterations = 8;
// Trials that end this far from the chosen pose are another pose.
constexpr double kOtherPoseDegrees = 30;

// The 24 turns that take the coordinate axes onto themselves (the cube's
// rotations): every signed permutation of determinant +1, the identity's
// order first.
std::vector<Eigen::Matrix3d> cube_rotations() {
  std::vector<Eigen::Matrix3d> turns;
  std::array<int, 3> order{0, 1, 2};
  do {
    for (const Eigen::Vector3d& sign : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1),
                                        Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1),
                                        Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-1, 1, 1),
                                        Eigen::Vector3d(1, -1, 1), Eigen::Vector3d(1, 1, -1)}) {
      Eigen::Matrix3d turn = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 3; ++k) turn(k, order[std::size_t(k)]) = sign(k);
      if (turn.determinant() > 0) turns.push_back(turn);
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return turns;
}

// The angle of the turn from `a` to `b`, in degrees.
double turn_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double cosine = std::clamp(((a.transpose() * b).trace() - 1) / 2, -1.0, 1.0);
  return std::acos(cosine) * 180 / std::numbers::pi;
}

// The vertices the fit uses: all, or every k-th of a large mesh.
PointSet fit_points(const PointSet& points) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (points.rows() + kMaxFitPoints - 1) / kMaxFitPoints);
  PointSet chosen((points.rows() + stride - 1) / stride, 3);
  for (Eigen::Index i = 0, k = 0; i < points.rows(); i += stride, ++k) chosen.row(k) = points.row(i);
  return chosen;
}

struct RigidFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rms = std::numeric_limits<double>::infinity();
  std::size_t iterations = 0;
};

// Iterative closest points: `moving` (already in the common frame) onto the
// tree's points, rotation and translation only (both are at unit area).
RigidFit closest_point_fit(const PointSet& moving, const PointSet& target, const MatrixRowTree<PointSet>& tree,
                           std::size_t max_iterations) {
  RigidFit fit;
  PointSet current = moving;
  PointSet matched(moving.rows(), 3);
  for (fit.iterations = 1; fit.iterations <= max_iterations; ++fit.iterations) {
    double squared = 0;
    for (Eigen::Index i = 0; i < current.rows(); ++i) {
      matched.row(i) = target.row(tree.nearest(current.row(i)).front());
      squared += (matched.row(i) - current.row(i)).squaredNorm();
    }
    const double rms = std::sqrt(squared / double(current.rows()));
    const bool settled = std::abs(fit.rms - rms) < kSettled;
    fit.rms = rms;
    if (settled) break;
    const Eigen::RowVector3d from = current.colwise().mean(), to = matched.colwise().mean();
    const Eigen::Matrix3d step = best_rotation(current.rowwise() - from, matched.rowwise() - to);
    current = ((current.rowwise() - from) * step.transpose()).rowwise() + to;
    fit.rotation = step * fit.rotation;
    fit.translation = step * (fit.translation - from.transpose()) + to.transpose();
  }
  fit.iterations = std::min(fit.iterations, max_iterations);
  return fit;
}

}  // namespace

PointSet vertex_points(const SurfaceMesh& mesh) {
  PointSet points(Eigen::Index(mesh.vertex_count()), 3);
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.positions()[v];
    points.row(Eigen::Index(v)) << p.x, p.y, p.z;
  }
  return points;
}

Similarity canonical_frame(const SurfaceMesh& mesh) {
  // Area-weighted moments of the surface, a triangle at its centroid.
  const PointSet points = vertex_points(mesh);
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d>> pieces;
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::Vector3d a = points.row(t[0]).transpose(), b = points.row(t[1]).transpose(),
                          c = points.row(t[2]).transpose();
    const double piece = 0.5 * (b - a).cross(c - a).norm();
    pieces.emplace_back(piece, (a + b + c) / 3.0);
    area += piece;
    centroid += piece * pieces.back().second;
  }
  centroid /= area;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& [piece, at] : pieces) second += piece * (at - centroid) * (at - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(second);
  Eigen::Matrix3d axes;  // rows: the axes, largest moment first
  for (int k = 0; k < 3; ++k) axes.row(k) = solver.eigenvectors().col(2 - k).transpose();
  std::array<double, 3> third{};
  for (const auto& [piece, at] : pieces) {
    for (int k = 0; k < 3; ++k) third[std::size_t(k)] += piece * std::pow(axes.row(k).dot(at - centroid), 3);
  }
  for (int k = 0; k < 3; ++k) {
    if (third[std::size_t(k)] < 0) axes.row(k) *= -1;
  }
  if (axes.determinant() < 0) axes.row(2) *= -1;  // a proper turn: the last axis yields
  Similarity frame;
  frame.scale = 1.0 / std::sqrt(area);
  frame.rotation = axes;
  frame.translation = -frame.scale * (axes * centroid);
  return frame;
}

MeshAlignment align_to_template(const SurfaceMesh& mesh, const PointSet& template_points,
                                const Similarity& template_frame) {
  const Similarity own = canonical_frame(mesh);
  // The starts: the pose as given (turned as the template's frame turns
  // the template: shapes of one scanner often arrive roughly aligned, and
  // on a nearly symmetric shape the principal axes are arbitrary), then the
  // shape's own principal axes onto the template's in each of the 24 proper
  // ways (the four sign patterns of their order first, then the other
  // orders: where two radii are close, the axes' order is arbitrary too).
  std::vector<Similarity> starts;
  Similarity as_given = own;
  as_given.rotation = template_frame.rotation;
  starts.push_back(as_given);
  for (const Eigen::Matrix3d& turn : cube_rotations()) {
    Similarity turned = own;
    turned.rotation = turn * own.rotation;
    starts.push_back(turned);
  }
  const PointSet world = fit_points(vertex_points(mesh));
  const MatrixRowTree<PointSet> tree(template_points);
  std::vector<RigidFit> trials;
  std::size_t chosen = 0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    Similarity& start = starts[k];
    start.translation = -start.scale * (start.rotation * world.colwise().mean().transpose());
    trials.push_back(closest_point_fit(start.apply(world), template_points, tree, kTrialIterations));
    // The given pose, or the first start in order, is kept unless another fits clearly better.
    if (trials[k].rms < kClearlyBetter * trials[chosen].rms) chosen = k;
  }
  const RigidFit& best = trials[chosen];
  const PointSet started = (starts[chosen].apply(world) * best.rotation.transpose()).rowwise() + best.translation.transpose();
  const RigidFit finish = closest_point_fit(started, template_points, tree, kMaxIterations);

  MeshAlignment alignment;
  alignment.from_principal_axes = chosen != 0;
  alignment.to_common.scale = starts[chosen].scale;
  alignment.to_common.rotation = finish.rotation * best.rotation * starts[chosen].rotation;
  alignment.to_common.translation =
      finish.rotation * (best.rotation * starts[chosen].translation + best.translation) + finish.translation;
  alignment.rms = finish.rms;
  alignment.iterations = best.iterations + finish.iterations;
  // The runner-up: the best trial that ended in another pose.
  const Eigen::Matrix3d chosen_turn = best.rotation * starts[chosen].rotation;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const double angle = turn_angle(chosen_turn, trials[k].rotation * starts[k].rotation);
    if (angle < kOtherPoseDegrees || trials[k].rms >= alignment.runner_up.rms) continue;
    alignment.runner_up = {trials[k].rms / best.rms, angle, trials[k].rms};
  }
  return alignment;
}

}  // namespace meshparticles
