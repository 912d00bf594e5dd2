#include "correspondence/mesh_alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>

#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

constexpr std::size_t kMaxIterations = 60;
constexpr double kSettled = 1e-9;            // rms change, unit-area units
constexpr Eigen::Index kMaxFitPoints = 4000;  // vertices fitted, evenly strided beyond

// The vertices the fit uses: all, or every k-th of a large mesh.
PointSet fit_points(const PointSet& points) { return strided_rows(points, std::size_t(kMaxFitPoints)); }

// A closest-point fit's map (x -> linear x + translation), the rms distance
// to the nearest points before its last step, and its iterations.
struct ClosestPointFit {
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rms = std::numeric_limits<double>::infinity();
  std::size_t iterations = 0;
};

// Iterative closest points: `moving` onto the tree's points, each step
// `refit(current, matched)` (which updates fit's map and returns the points
// moved by it), until the rms distance to the nearest settles.
template <typename Refit>
ClosestPointFit iterate_closest_points(const PointSet& moving, const PointSet& target, const PointsTree& tree,
                                       std::size_t max_iterations, ClosestPointFit& fit, Refit&& refit) {
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
    current = refit(current, matched);
  }
  fit.iterations = std::min(fit.iterations, max_iterations);
  return fit;
}

// `moving` (already in the common frame) onto the tree's points, rotation
// and translation only (both are at unit area).
ClosestPointFit closest_point_fit(const PointSet& moving, const PointSet& target, const PointsTree& tree,
                                  std::size_t max_iterations) {
  ClosestPointFit fit;
  return iterate_closest_points(moving, target, tree, max_iterations, fit, [&](const PointSet& current, const PointSet& matched) {
    const Eigen::RowVector3d from = current.colwise().mean(), to = matched.colwise().mean();
    const Eigen::Matrix3d step = best_rotation(current.rowwise() - from, matched.rowwise() - to);
    fit.linear = step * fit.linear;
    fit.translation = step * (fit.translation - from.transpose()) + to.transpose();
    return PointSet(((current.rowwise() - from) * step.transpose()).rowwise() + to);
  });
}

// `moving` onto the tree's points by an affine map, each step the least-squares one onto the nearest points.
ClosestPointFit affine_closest_point_fit(const PointSet& moving, const PointSet& target, const PointsTree& tree,
                                         std::size_t max_iterations) {
  Eigen::MatrixXd homogeneous(moving.rows(), 4);
  homogeneous.leftCols(3) = moving;
  homogeneous.col(3).setOnes();
  const Eigen::LDLT<Eigen::Matrix4d> solver(homogeneous.transpose() * homogeneous);
  ClosestPointFit fit;
  return iterate_closest_points(moving, target, tree, max_iterations, fit, [&](const PointSet&, const PointSet& matched) {
    const Eigen::Matrix<double, 4, 3> map = solver.solve(homogeneous.transpose() * matched);
    fit.linear = map.topRows(3).transpose();
    fit.translation = map.row(3).transpose();
    return PointSet((moving * fit.linear.transpose()).rowwise() + fit.translation.transpose());
  });
}

// The rotation nearest a linear map (its polar factor).
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& linear) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0) u.col(2) *= -1;
  return u * svd.matrixV().transpose();
}

}  // namespace

double turn_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double cosine = std::clamp(((a.transpose() * b).trace() - 1) / 2, -1.0, 1.0);
  return std::acos(cosine) * 180 / std::numbers::pi;
}

const std::vector<Eigen::Matrix3d>& cube_rotations() {
  static const std::vector<Eigen::Matrix3d> turns = [] {
    std::vector<Eigen::Matrix3d> found;
    std::array<int, 3> order{0, 1, 2};
    do {
      for (const Eigen::Vector3d& sign : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1),
                                          Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1),
                                          Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-1, 1, 1),
                                          Eigen::Vector3d(1, -1, 1), Eigen::Vector3d(1, 1, -1)}) {
        Eigen::Matrix3d turn = Eigen::Matrix3d::Zero();
        for (int k = 0; k < 3; ++k) turn(k, order[std::size_t(k)]) = sign(k);
        if (turn.determinant() > 0) found.push_back(turn);
      }
    } while (std::next_permutation(order.begin(), order.end()));
    return found;
  }();
  return turns;
}

double mean_squared_to_nearest(const PointSet& a, const PointSet& b, const PointsTree& b_tree) {
  double squared = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) squared += (b.row(b_tree.nearest(a.row(i)).front()) - a.row(i)).squaredNorm();
  return squared / double(std::max<Eigen::Index>(1, a.rows()));
}

double shape_distance(const PointSet& a, const PointsTree& a_tree, const PointSet& b, const PointsTree& b_tree) {
  return std::sqrt(0.5 * (mean_squared_to_nearest(a, b, b_tree) + mean_squared_to_nearest(b, a, a_tree)));
}

PointSet strided_rows(const PointSet& points, std::size_t most) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (points.rows() + Eigen::Index(most) - 1) / Eigen::Index(most));
  PointSet chosen((points.rows() + stride - 1) / stride, 3);
  for (Eigen::Index i = 0, k = 0; i < points.rows(); i += stride, ++k) chosen.row(k) = points.row(i);
  return chosen;
}

PointSet alignment_points(const SurfaceMesh& mesh) { return fit_points(vertex_points(mesh)); }

AlignedShapes::AlignedShapes(std::vector<PointSet> aligned) : shapes_(std::move(aligned)) {
  for (const PointSet& points : shapes_) trees_.push_back(std::make_unique<PointsTree>(points));
}

std::size_t AlignedShapes::medoid() const {
  std::vector<double> sums(shapes_.size(), 0.0);
  for (std::size_t a = 0; a < shapes_.size(); ++a) {
    for (std::size_t b = a + 1; b < shapes_.size(); ++b) {
      const double distance = shape_distance(shapes_[a], *trees_[a], shapes_[b], *trees_[b]);
      sums[a] += distance;
      sums[b] += distance;
    }
  }
  return std::size_t(std::min_element(sums.begin(), sums.end()) - sums.begin());
}

double AlignedShapes::distance_to_population(const PointSet& placed, std::size_t self) const {
  const PointsTree tree(placed);
  double sum = 0;
  for (std::size_t b = 0; b < shapes_.size(); ++b) {
    if (b != self) sum += shape_distance(placed, tree, shapes_[b], *trees_[b]);
  }
  return sum;
}

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

PoseTrials pose_trials(const SurfaceMesh& mesh, const PointSet& template_points, const Similarity& template_frame,
                       const PointsTree& template_tree, const PoseChoiceOptions& options) {
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
  PoseTrials found;
  found.points = fit_points(vertex_points(mesh));
  // Each start is judged by an affine fit: a stretch of the whole shape
  // costs nothing, so the radii, which vary from shape to shape, do not
  // outvote the features that say which way round it is.
  for (Similarity& start : starts) {
    start.translation = -start.scale * (start.rotation * found.points.colwise().mean().transpose());
    const ClosestPointFit fit = affine_closest_point_fit(start.apply(found.points), template_points, template_tree,
                                                         options.trial_iterations);
    found.trials.push_back({start, fit.linear, fit.translation, fit.rms, nearest_rotation(fit.linear) * start.rotation});
    if (fit.rms < found.trials[found.best].rms) found.best = found.trials.size() - 1;
  }
  const std::vector<PoseTrial>& trials = found.trials;
  // The best start takes the place of the pose as given only where it
  // ends in another pose and fits clearly better.
  const bool another_pose = turn_angle(trials.front().turn, trials[found.best].turn) >= options.same_pose_degrees;
  found.chosen = another_pose && clearly_lower(trials[found.best].rms, trials.front().rms, options.given_pose_kept)
                     ? found.best
                     : 0;
  return found;
}

std::vector<std::size_t> distinct_poses(const std::vector<double>& rms, const std::vector<Eigen::Matrix3d>& turns,
                                        std::vector<std::size_t> kept, double within, double degrees) {
  std::vector<std::size_t> order(rms.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rms[a] < rms[b]; });
  for (const std::size_t k : order) {
    if (rms[k] > within * rms[order.front()]) break;
    const bool another = std::all_of(kept.begin(), kept.end(), [&](std::size_t p) {
      return turn_angle(turns[p], turns[k]) >= degrees;
    });
    if (another) kept.push_back(k);
  }
  return kept;
}

std::vector<std::size_t> PoseTrials::distinct_poses(const PoseChoiceOptions& options) const {
  std::vector<double> rms;
  std::vector<Eigen::Matrix3d> turns;
  for (const PoseTrial& trial : trials) {
    rms.push_back(trial.rms);
    turns.push_back(trial.turn);
  }
  return meshparticles::distinct_poses(rms, turns, {chosen}, options.open_pose_ratio, options.same_pose_degrees);
}

MeshAlignment fit_pose(const PoseTrials& found, std::size_t chosen, const PointSet& template_points,
                       const PointsTree& template_tree, const PoseChoiceOptions& options) {
  const PoseTrial& start = found.trials[chosen];
  // The pose itself: rigid, from the chosen start (a short fit, then to the end).
  const PointSet started = start.start.apply(found.points);
  const ClosestPointFit first = closest_point_fit(started, template_points, template_tree, options.trial_iterations);
  const PointSet placed = (started * first.linear.transpose()).rowwise() + first.translation.transpose();
  const ClosestPointFit finish = closest_point_fit(placed, template_points, template_tree, kMaxIterations);

  MeshAlignment alignment;
  alignment.from_principal_axes = chosen != 0;
  alignment.to_common.scale = start.start.scale;
  alignment.to_common.rotation = finish.linear * first.linear * start.start.rotation;
  alignment.to_common.translation =
      finish.linear * (first.linear * start.start.translation + first.translation) + finish.translation;
  alignment.rms = finish.rms;
  alignment.iterations = first.iterations + finish.iterations;
  // The runner-up: the best trial that ended in another pose.
  for (const PoseTrial& trial : found.trials) {
    const double angle = turn_angle(start.turn, trial.turn);
    if (angle < options.same_pose_degrees || trial.rms >= alignment.runner_up.rms) continue;
    alignment.runner_up = {trial.rms / start.rms, angle, trial.rms};
  }
  return alignment;
}

MeshAlignment align_to_template(const SurfaceMesh& mesh, const PointSet& template_points,
                                const Similarity& template_frame, const PoseChoiceOptions& options) {
  const PointsTree tree(template_points);
  const PoseTrials found = pose_trials(mesh, template_points, template_frame, tree, options);
  return fit_pose(found, found.chosen, template_points, tree, options);
}

}  // namespace meshparticles
