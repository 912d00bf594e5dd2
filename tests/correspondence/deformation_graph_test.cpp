// The embedded deformation graph (correspondence/deformation_graph): it
// leaves a shape equal to the template where it is, follows a rigid motion,
// follows a capsule bent at a joint where the smoothed displacement of
// template_deformation cannot, and joins only nodes that are neighbours on
// the surface, never two arms that touch in space.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "correspondence/deformation_graph.hpp"
#include "correspondence/template_deformation.hpp"

namespace meshparticles::testing {
namespace {

constexpr double kRadius = 0.5;
constexpr double kLength = 8;  // of the cylinder between the caps

// A closed capsule along z: a cylinder of kRadius from z = 0 to kLength and
// a hemisphere on each end, `around` vertices a ring, rings about as far
// apart as the vertices of a ring.
SurfaceMesh capsule(int around) {
  const double step = 2 * std::numbers::pi * kRadius / around;
  const int cap_rings = std::max(2, int(std::lround(std::numbers::pi / 2 * kRadius / step)));
  const int body_rings = int(std::lround(kLength / step));
  std::vector<Vec3> positions{{0, 0, -kRadius}};
  std::vector<std::pair<double, double>> rings;  // (z, ring radius)
  for (int i = 1; i <= cap_rings; ++i) {
    const double polar = std::numbers::pi / 2 * (1 - double(i) / cap_rings);
    rings.emplace_back(-kRadius * std::sin(polar), kRadius * std::cos(polar));
  }
  for (int i = 1; i <= body_rings; ++i) rings.emplace_back(kLength * i / body_rings, kRadius);
  for (int i = cap_rings - 1; i >= 1; --i) {
    const double polar = std::numbers::pi / 2 * (1 - double(i) / cap_rings);
    rings.emplace_back(kLength + kRadius * std::sin(polar), kRadius * std::cos(polar));
  }
  for (const auto& [z, r] : rings) {
    for (int a = 0; a < around; ++a) {
      const double angle = 2 * std::numbers::pi * a / around;
      positions.push_back({r * std::cos(angle), r * std::sin(angle), z});
    }
  }
  positions.push_back({0, 0, kLength + kRadius});
  const auto at = [&](std::size_t ring, int a) { return VertexId(1 + ring * around + std::size_t((a + around) % around)); };
  std::vector<Triangle> triangles;
  for (int a = 0; a < around; ++a) triangles.push_back({0, at(0, a + 1), at(0, a)});
  for (std::size_t ring = 0; ring + 1 < rings.size(); ++ring) {
    for (int a = 0; a < around; ++a) {
      triangles.push_back({at(ring, a), at(ring, a + 1), at(ring + 1, a + 1)});
      triangles.push_back({at(ring, a), at(ring + 1, a + 1), at(ring + 1, a)});
    }
  }
  const VertexId top = VertexId(positions.size() - 1);
  for (int a = 0; a < around; ++a) triangles.push_back({top, at(rings.size() - 1, a), at(rings.size() - 1, a + 1)});
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

PointSet points_of(const SurfaceMesh& mesh) {
  PointSet points(Eigen::Index(mesh.vertex_count()), 3);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.positions()[v];
    points.row(Eigen::Index(v)) << p.x, p.y, p.z;
  }
  return points;
}

// The capsule bent towards +x by `angle` over an arc of `joint` length about
// the middle of its axis; straight on either side of it.
struct Bend {
  double angle, joint;
  double start() const { return (kLength - joint) / 2; }
  Eigen::RowVector3d operator()(const Eigen::RowVector3d& p) const {
    const double radius = joint / angle;
    const double along = std::clamp(p.z() - start(), 0.0, joint);
    const double turn = along / radius;
    Eigen::RowVector3d bent(radius - (radius - p.x()) * std::cos(turn), p.y(), start() + (radius - p.x()) * std::sin(turn));
    if (p.z() < start()) bent.z() = p.z();
    if (p.z() > start() + joint) bent += (p.z() - start() - joint) * Eigen::RowVector3d(std::sin(angle), 0, std::cos(angle));
    return bent;
  }
  PointSet operator()(const PointSet& points) const {
    PointSet bent(points.rows(), 3);
    for (Eigen::Index v = 0; v < points.rows(); ++v) bent.row(v) = (*this)(Eigen::RowVector3d(points.row(v)));
    return bent;
  }
};

SurfaceMesh mesh_at(const SurfaceMesh& mesh, const PointSet& points) {
  std::vector<Vec3> positions;
  for (Eigen::Index v = 0; v < points.rows(); ++v) positions.push_back({points(v, 0), points(v, 1), points(v, 2)});
  return SurfaceMesh(std::move(positions), mesh.triangles());
}

double rms_apart(const PointSet& a, const PointSet& b) { return std::sqrt((a - b).rowwise().squaredNorm().mean()); }

TEST(DeformationGraph, CapsuleIsClosedAndFacesOutward) {
  const SurfaceMesh mesh = capsule(24);
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
  double volume = 0;  // six times, by the divergence theorem
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 &a = mesh.positions()[t[0]], &b = mesh.positions()[t[1]], &c = mesh.positions()[t[2]];
    volume += dot(a, cross(b, c));
  }
  const double expected = std::numbers::pi * kRadius * kRadius * (kLength + 4 * kRadius / 3);
  EXPECT_NEAR(volume / 6, expected, 0.03 * expected);
}

TEST(DeformationGraph, AShapeEqualToTheTemplateStaysWhereItIs) {
  const SurfaceMesh mesh = capsule(24);
  const PointSet points = points_of(mesh);
  const GraphFit fit = deform_by_graph(mesh, points, mesh, points);
  EXPECT_EQ(fit.nodes, mesh.vertex_count() / 25);
  EXPECT_LT((fit.moved - points).cwiseAbs().maxCoeff(), 1e-9 * kLength);
  EXPECT_LT(fit.rms, 1e-9 * kLength);
}

TEST(DeformationGraph, FollowsARigidMotion) {
  const SurfaceMesh mesh = capsule(24);
  const PointSet points = points_of(mesh);
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 0.5).normalized())).toRotationMatrix();
  const PointSet moved = (points * turn.transpose()).rowwise() + Eigen::RowVector3d(0.3, -0.2, 0.5);
  const GraphFit fit = deform_by_graph(mesh, points, mesh, moved);
  EXPECT_LT(fit.rms, 1e-3 * kLength);
  EXPECT_LT(rms_apart(fit.moved, moved), 1e-3 * kLength);
}

// Why the module exists: a capsule bent by 80 degrees at a joint in its
// middle. The graph bends with it, and its far end lands where the bend put
// it; the smoothed displacement leaves the far end well short of it.
TEST(DeformationGraph, FollowsAJointThatTheSmoothedDisplacementCannot) {
  const SurfaceMesh mesh = capsule(24);
  const PointSet points = points_of(mesh);
  const Bend bend{80 * std::numbers::pi / 180, 1.5};
  const PointSet bent = bend(points);
  const SurfaceMesh bent_mesh = mesh_at(mesh, bent);
  const Eigen::Index tip = Eigen::Index(mesh.vertex_count() - 1);  // the pole at the far end
  const double bound = 0.02 * kLength;

  const GraphFit fit = deform_by_graph(mesh, points, bent_mesh, bent);
  EXPECT_LT(fit.rms, bound);
  EXPECT_LT((fit.moved.row(tip) - bent.row(tip)).norm(), 2 * bound);
  EXPECT_LT(rms_apart(fit.moved, bent), 2 * bound);

  const PointSet smoothed = deform_template(mesh, points, bent);
  EXPECT_GT((smoothed.row(tip) - bent.row(tip)).norm(), 4 * bound);
}

// A capsule a third longer and thinner (a taller, slimmer body): each node
// must stretch with it. A stiffness ending at 0.125 left the template 0.035
// off the surface (rms), features and all: FAUST's people least like the
// template slid about a spacing up the body. (Along a featureless capsule
// nothing fixes where each vertex lands, so only the surface is held here.)
TEST(DeformationGraph, ReachesAShapeOfOtherProportions) {
  const SurfaceMesh mesh = capsule(24);
  const PointSet points = points_of(mesh);
  const PointSet stretched = points * Eigen::Vector3d(0.85, 0.85, 1.3).asDiagonal();
  const GraphFit fit = deform_by_graph(mesh, points, mesh_at(mesh, stretched), stretched);
  EXPECT_LT(fit.rms, 1e-3 * kLength);
}

// The coarse mode (for comparing the poses a rigid fit leaves open): a
// node for each 100 vertices (here the least, 32), fewer fits a stage, and
// still the joint followed.
TEST(DeformationGraph, CoarseModeFollowsTheJointWithFewerNodes) {
  const SurfaceMesh mesh = capsule(24);
  const PointSet points = points_of(mesh);
  const PointSet bent = Bend{80 * std::numbers::pi / 180, 1.5}(points);
  const GraphFit fit = deform_by_graph(mesh, points, mesh_at(mesh, bent), bent, coarse_deformation_graph_options());
  const Eigen::Index tip = Eigen::Index(mesh.vertex_count() - 1);
  EXPECT_EQ(fit.nodes, 32u);
  EXPECT_LT(fit.rms, 0.02 * kLength);
  EXPECT_LT((fit.moved.row(tip) - bent.row(tip)).norm(), 0.04 * kLength);
}

// Two arms of a U lie side by side a tenth of their radius apart: no edge
// of the graph joins a node of one arm to a node of the other (they are
// twice the node spacing apart on the surface), and no vertex of one arm
// moves with a node of the other.
TEST(DeformationGraph, EdgesJoinNeighboursOnTheSurfaceNotInSpace) {
  const SurfaceMesh straight = capsule(24);
  const Bend bend{std::numbers::pi, std::numbers::pi * 1.1 * kRadius};
  const PointSet points = bend(points_of(straight));
  const SurfaceMesh mesh = mesh_at(straight, points);
  const DeformationGraph graph = build_deformation_graph(mesh);
  // -1: the first arm, +1: the second, 0: the bend and a margin either side.
  const double margin = 1.0;
  const auto arm = [&](VertexId v) {
    const double z = straight.positions()[v].z;
    return z < bend.start() - margin ? -1 : z > bend.start() + bend.joint + margin ? 1 : 0;
  };
  // The arms do come within the node spacing of each other in space.
  double nearest_across = std::numeric_limits<double>::infinity();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    for (VertexId w = 0; w < mesh.vertex_count(); ++w) {
      if (arm(v) == -1 && arm(w) == 1) nearest_across = std::min(nearest_across, (points.row(v) - points.row(w)).norm());
    }
  }
  EXPECT_LT(nearest_across, 0.25 * graph.spacing);

  std::size_t across = 0, within = 0;
  for (const auto& [a, b] : graph.edges) {
    const int arm_a = arm(graph.nodes[a]), arm_b = arm(graph.nodes[b]);
    if (arm_a * arm_b == -1) ++across;
    if (arm_a != 0 && arm_a == arm_b) ++within;
  }
  EXPECT_EQ(across, 0u);
  EXPECT_GT(within, graph.nodes.size());  // the arms are joined within themselves
  std::size_t moved_across = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    for (std::uint32_t i = graph.influence_offsets[v]; i < graph.influence_offsets[v + 1]; ++i) {
      if (arm(v) * arm(graph.nodes[graph.influence_nodes[i]]) == -1) ++moved_across;
    }
  }
  EXPECT_EQ(moved_across, 0u);
}

}  // namespace
}  // namespace meshparticles::testing
