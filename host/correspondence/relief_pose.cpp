#include "correspondence/relief_pose.hpp"

#include "correspondence/surface_relief.hpp"

namespace meshparticles {

namespace {

// Points of the common frame as `pose` placed the shape, in the shape's own
// coordinates: where two poses' fits put the template on the shape itself.
PointSet in_shape_frame(const MeshAlignment& pose, const PointSet& common) {
  const Similarity& to_common = pose.to_common;
  return (common.rowwise() - to_common.translation.transpose()) * to_common.rotation / to_common.scale;
}

}  // namespace

ReliefTemplate::ReliefTemplate(const SurfaceMesh& template_mesh, const PointSet& template_points,
                               const PoseChoiceOptions& choice_options)
    : mesh(template_mesh),
      points(template_points),
      relief(detrended_relief(template_mesh, template_points)),
      graph(template_graph(template_mesh, template_points, coarse_deformation_graph_options())),
      options(choice_options) {}

ReliefChoice choose_pose_by_relief(const ReliefTemplate& reference, const SurfaceMesh& mesh,
                                   const std::vector<MeshAlignment>& poses) {
  const PointSet own = vertex_points(mesh);
  const Eigen::VectorXd relief = detrended_relief(mesh, own);
  std::vector<double> agreements;
  std::vector<PointSet> ends;  // the template's vertices after each pose's fit, on the shape
  for (const MeshAlignment& pose : poses) {
    const PointSet placed = pose.to_common.apply(own);
    const PointsTree tree(placed);
    const PointSet moved =
        deform_by_graph(reference.graph, reference.mesh, reference.points, mesh, placed, coarse_deformation_graph_options())
            .moved;
    std::vector<Eigen::Index> pairs(std::size_t(moved.rows()));
    for (Eigen::Index v = 0; v < moved.rows(); ++v) pairs[std::size_t(v)] = tree.nearest(moved.row(v)).front();
    agreements.push_back(relief_agreement(reference.relief, relief, pairs));
    ends.push_back(in_shape_frame(pose, moved));
  }
  std::vector<Eigen::Matrix3d> turns;
  for (const MeshAlignment& pose : poses) turns.push_back(pose.to_common.rotation);
  ReliefChoice choice;
  // At unit area, as the common frame is; the chosen's own end is its own.
  const auto same_end = [&](std::size_t c, std::size_t chosen) {
    const double apart = (ends[c] - ends[chosen]).rowwise().norm().mean() * poses[chosen].to_common.scale;
    return apart < reference.options.same_end_state;
  };
  choice.chosen = choose_by_agreement(agreements, turns, same_end, choice.relief);
  return choice;
}

}  // namespace meshparticles
