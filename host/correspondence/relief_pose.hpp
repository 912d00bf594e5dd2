#pragma once
// Which of the poses a shape's rigid fit leaves open it takes: the one in
// which the template, bent onto it by a coarse deformation graph, lays its
// relief (detrended_relief: bumps, a nose, hands, less what a bend adds)
// over the shape's own. A rigid fit prefers whatever dominates the
// silhouette (a bend, a raised arm); only once the large motion is taken
// out do the small features decide, and they decide by where they land,
// not by how far the surfaces lie apart (every pose of a bent body ends
// within 1% of the same residual after the graph's fit, measured on the
// bent-either family).
#include <cstddef>
#include <vector>

#include "correspondence/deformation_graph.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_choice_options.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct ReliefChoice {
  std::size_t chosen = 0;  // into the poses given
  MeshAlignment::Relief relief{true};
};

// The template's side of the choice, the same for every shape: its
// vertices in the common frame, their surface_relief, and its coarse
// deformation graph there.
struct ReliefTemplate {
  ReliefTemplate(const SurfaceMesh& template_mesh, const PointSet& template_points, const PoseChoiceOptions& options);
  const SurfaceMesh& mesh;
  PointSet points;
  Eigen::VectorXd relief;
  DeformationGraph graph;
  PoseChoiceOptions options;
};

// `poses`: the shape's open poses, rigidly fitted (the fit's choice first).
// Ties keep the earlier pose. Poses whose fits end within the options'
// same_end_state of the chosen one's are no runner-up.
ReliefChoice choose_pose_by_relief(const ReliefTemplate& reference, const SurfaceMesh& mesh,
                                   const std::vector<MeshAlignment>& poses);

}  // namespace meshparticles
