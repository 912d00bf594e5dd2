#include "correspondence/body_turn.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/parallel_for.hpp"
#include "mesh/point_cloud_tree.hpp"

namespace meshparticles {

namespace {

using DirectionTree = MatrixRowTree<PointSet>;

}  // namespace

ProfileGrid profile_grid(std::size_t count) {
  ProfileGrid grid;
  grid.directions.resize(Eigen::Index(count), 3);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1 - (2 * double(i) + 1) / double(count);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    grid.directions.row(Eigen::Index(i)) << r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z;
  }
  const DirectionTree tree(grid.directions);
  for (const Eigen::Matrix3d& turn : cube_rotations()) {
    const PointSet turned = grid.directions * turn.transpose();
    std::vector<Eigen::Index>& nearest = grid.turned.emplace_back(count);
    for (Eigen::Index g = 0; g < turned.rows(); ++g) {
      nearest[std::size_t(g)] = Eigen::Index(tree.nearest(turned.row(g)).front());
    }
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
                                    const ProfileGrid& grid) {
  const Eigen::Index count = grid.directions.rows();
  std::vector<double> agreements;
  for (const std::vector<Eigen::Index>& nearest : grid.turned) {
    double sum = 0;
    for (Eigen::Index g = 0; g < count; ++g) sum += profile(g) * reference(nearest[std::size_t(g)]);
    agreements.push_back(sum / double(count));
  }
  return agreements;
}

Eigen::VectorXd turned_profile(const Eigen::VectorXd& profile, const ProfileGrid& grid, std::size_t turn) {
  // The reference's direction h holds the profile's value at T^-1 h.
  const std::vector<Eigen::Matrix3d>& turns = cube_rotations();
  std::size_t inverse = 0;
  while (inverse + 1 < turns.size() && !(turns[inverse] * turns[turn]).isIdentity(1e-12)) ++inverse;
  const std::vector<Eigen::Index>& nearest = grid.turned[inverse];
  Eigen::VectorXd turned(grid.directions.rows());
  for (Eigen::Index h = 0; h < turned.size(); ++h) turned(h) = profile(nearest[std::size_t(h)]);
  return turned;
}

void choose_body_turns(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                       const PointSet& template_points, std::vector<MeshAlignment>& alignments,
                       const PoseChoiceOptions& options) {
  const std::optional<EllipsoidBody> reference = ellipsoid_body(template_points);
  if (!reference) return;
  const std::size_t count = meshes.size();
  const std::vector<std::size_t> owned = share.owned();
  const ProfileGrid grid = profile_grid(options.profile_directions);
  const Eigen::Index directions = grid.directions.rows();
  const std::vector<Eigen::Matrix3d>& turns = cube_rotations();
  std::vector<std::optional<EllipsoidBody>> bodies(count);
  std::vector<std::vector<double>> message(count);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const PointSet vertices = k == 0 ? template_points : vertex_points(*meshes[k]);
    bodies[k] = k == 0 ? reference : ellipsoid_body(vertices);
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
    const Eigen::VectorXd profile = feature_profile(*bodies[k], vertices, grid.directions);
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
    profiles[k] = Eigen::Map<const Eigen::VectorXd>(message[k].data() + 1, directions);
    placed[k] = turned_profile(profiles[k], grid, chosen[k]);
  }
  if (with_body.size() < 3) return;
  std::vector<std::vector<double>> agreements(count);
  const auto others = [&](std::size_t k) {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(directions);
    for (const std::size_t j : with_body) {
      if (j != k) sum += placed[j];
    }
    return Eigen::VectorXd(sum / double(with_body.size() - 1));
  };
  for (std::size_t round = 0; round < options.body_turn_rounds; ++round) {
    bool changed = false;
    for (const std::size_t k : with_body) {
      agreements[k] = turn_agreements(profiles[k], others(k), grid);
      if (k == 0) continue;  // the template's turn is the common frame's
      const std::size_t best = std::size_t(std::max_element(agreements[k].begin(), agreements[k].end()) - agreements[k].begin());
      const double held = agreements[k][chosen[k]];
      if (best == chosen[k] || !clearly_higher(agreements[k][best], held, options.clearly_better_turn)) continue;
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
      alignment.runner_up = {ratio, turn_angle(other, pose.rotation), agreement[t]};
    }
  }
}

}  // namespace meshparticles
