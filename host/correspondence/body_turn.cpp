#include "correspondence/body_turn.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "common/parallel_for.hpp"
#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

using DirectionTree = MatrixRowTree<PointSet>;

// Directions at which bodies' features are compared, and rounds of choosing turns.
constexpr Eigen::Index kProfileDirections = 2000;
constexpr std::size_t kBodyTurnRounds = 5;
// A shape leaves the turn it has only for one whose features agree this
// much better with the others': where two agree about as well (a shape
// with faint features), its fit onto the template decides.
constexpr double kClearlyBetter = 1.1;

// For each cube rotation T, each grid direction's nearest grid direction after T.
std::vector<std::vector<Eigen::Index>> turned_indices(const PointSet& grid) {
  const DirectionTree tree(grid);
  std::vector<std::vector<Eigen::Index>> indices;
  for (const Eigen::Matrix3d& turn : cube_rotations()) {
    const PointSet turned = grid * turn.transpose();
    std::vector<Eigen::Index>& nearest = indices.emplace_back(std::size_t(grid.rows()));
    for (Eigen::Index g = 0; g < grid.rows(); ++g) {
      nearest[std::size_t(g)] = Eigen::Index(tree.nearest(turned.row(g)).front());
    }
  }
  return indices;
}

}  // namespace

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

PointSet sphere_directions(std::size_t count) {
  PointSet grid(Eigen::Index(count), 3);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1 - (2 * double(i) + 1) / double(count);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    grid.row(Eigen::Index(i)) << r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z;
  }
  return grid;
}

Eigen::VectorXd feature_profile(const EllipsoidBody& body, const PointSet& points, const PointSet& grid) {
  const PointSet sphere = body.to_unit_sphere(points);
  const PointSet directions = sphere.rowwise().normalized();
  const DirectionTree tree(directions);
  Eigen::VectorXd profile(grid.rows());
  for (Eigen::Index g = 0; g < grid.rows(); ++g) {
    profile(g) = sphere.row(Eigen::Index(tree.nearest(grid.row(g)).front())).norm() - 1;
  }
  return profile;
}

std::vector<double> turn_agreements(const Eigen::VectorXd& profile, const Eigen::VectorXd& reference,
                                    const PointSet& grid) {
  std::vector<double> agreements;
  for (const std::vector<Eigen::Index>& nearest : turned_indices(grid)) {
    double sum = 0;
    for (Eigen::Index g = 0; g < grid.rows(); ++g) sum += profile(g) * reference(nearest[std::size_t(g)]);
    agreements.push_back(sum / double(grid.rows()));
  }
  return agreements;
}

Eigen::VectorXd turned_profile(const Eigen::VectorXd& profile, const PointSet& grid, std::size_t turn) {
  // The reference's direction h holds the profile's value at T^-1 h.
  const std::vector<Eigen::Matrix3d>& turns = cube_rotations();
  std::size_t inverse = 0;
  while (inverse + 1 < turns.size() && !(turns[inverse] * turns[turn]).isIdentity(1e-12)) ++inverse;
  const std::vector<Eigen::Index> nearest = turned_indices(grid)[inverse];
  Eigen::VectorXd turned(grid.rows());
  for (Eigen::Index h = 0; h < grid.rows(); ++h) turned(h) = profile(nearest[std::size_t(h)]);
  return turned;
}

void choose_body_turns(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                       const PointSet& template_points, std::vector<MeshAlignment>& alignments) {
  const std::optional<EllipsoidBody> reference = ellipsoid_body(template_points);
  if (!reference) return;
  const std::size_t count = meshes.size();
  const std::vector<std::size_t> owned = share.owned();
  const PointSet grid = sphere_directions(kProfileDirections);
  const std::vector<Eigen::Matrix3d>& turns = cube_rotations();
  std::vector<std::optional<EllipsoidBody>> bodies(count);
  std::vector<std::vector<double>> message(count);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const PointSet vertices = vertex_points(*meshes[k]);
    bodies[k] = ellipsoid_body(k == 0 ? template_points : vertices);
    if (!bodies[k]) return;
    std::size_t turn = 0;
    // How far turn t's pose lies from the fitted one (3 less the trace: 0 for the same pose).
    const auto apart = [&](std::size_t t) {
      const Eigen::Matrix3d candidate = reference->axes.transpose() * turns[t] * bodies[k]->axes;
      return 3 - (candidate.transpose() * alignments[k].to_common.rotation).trace();
    };
    for (std::size_t t = 1; t < turns.size(); ++t) {
      if (apart(t) < apart(turn)) turn = t;
    }
    const Eigen::VectorXd profile = feature_profile(*bodies[k], k == 0 ? template_points : vertices, grid);
    message[k].push_back(double(turn));
    message[k].insert(message[k].end(), profile.begin(), profile.end());
  });
  share.gather(message);
  std::vector<std::size_t> chosen(count);
  std::vector<Eigen::VectorXd> profiles(count), placed(count);
  std::vector<std::size_t> with_body;
  for (std::size_t k = 0; k < count; ++k) {
    if (message[k].empty()) continue;
    with_body.push_back(k);
    chosen[k] = std::size_t(message[k].front());
    profiles[k] = Eigen::Map<const Eigen::VectorXd>(message[k].data() + 1, grid.rows());
    placed[k] = turned_profile(profiles[k], grid, chosen[k]);
  }
  if (with_body.size() < 3) return;
  std::vector<std::vector<double>> agreements(count);
  const auto others = [&](std::size_t k) {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(grid.rows());
    for (const std::size_t j : with_body) {
      if (j != k) sum += placed[j];
    }
    return Eigen::VectorXd(sum / double(with_body.size() - 1));
  };
  for (std::size_t round = 0; round < kBodyTurnRounds; ++round) {
    bool changed = false;
    for (const std::size_t k : with_body) {
      agreements[k] = turn_agreements(profiles[k], others(k), grid);
      if (k == 0) continue;  // the template's turn is the common frame's
      const std::size_t best = std::size_t(std::max_element(agreements[k].begin(), agreements[k].end()) - agreements[k].begin());
      const double held = agreements[k][chosen[k]];
      if (best == chosen[k] || (held > 0 && agreements[k][best] < kClearlyBetter * held)) continue;
      chosen[k] = best;
      placed[k] = turned_profile(profiles[k], grid, best);
      changed = true;
    }
    if (!changed) break;
  }
  for (const std::size_t k : owned) {
    if (!bodies[k] || k == 0) continue;
    MeshAlignment& alignment = alignments[k];
    Similarity& pose = alignment.to_common;
    const std::vector<double>& agreement = agreements[k];
    alignment.from_principal_axes = true;  // its body's
    pose.rotation = reference->axes.transpose() * turns[chosen[k]] * bodies[k]->axes;
    pose.translation = reference->centre - pose.scale * (pose.rotation * bodies[k]->centre);
    // Its body's radii, in the common frame, along the template's axes.
    const Eigen::Vector3d radii = turns[chosen[k]].cwiseAbs() * bodies[k]->radii * pose.scale;
    alignment.stretch = reference->axes.transpose() * reference->radii.cwiseQuotient(radii).asDiagonal() * reference->axes;
    alignment.shift = reference->centre - alignment.stretch * reference->centre;
    alignment.runner_up = {};
    for (std::size_t t = 0; t < turns.size(); ++t) {
      if (t == chosen[k] || agreement[t] <= 0) continue;
      const double ratio = agreement[chosen[k]] / agreement[t];
      if (ratio >= alignment.runner_up.rms_ratio) continue;
      const Eigen::Matrix3d other = reference->axes.transpose() * turns[t] * bodies[k]->axes;
      const double cosine = std::clamp(((other.transpose() * pose.rotation).trace() - 1) / 2, -1.0, 1.0);
      alignment.runner_up = {ratio, std::acos(cosine) * 180 / std::numbers::pi, agreement[t]};
    }
  }
}

}  // namespace meshparticles
