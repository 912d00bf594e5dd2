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
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// A pose's agreement (MeshAlignment::Relief) within this of the best
// other's, or under kSureRelief in every pose, is warned of
// (population_doubts); under kWeakRelief the canonical form decides
// (canonical_pose). Measured at n = 256 with the detrended relief: on the
// one-way bent families the right pose agrees 0.51 to 0.75 and the half
// turn 0.06 to 0.34; on bent-either, shapes bent the template's way 0.59
// to 0.65, those bent the other way at most 0.30 in any pose (the coarse
// fit cannot carry the template through a bend reversed); on FAUST's poses
// the right pose 0.43 to 0.89, the runner-up 0.01 to 0.60, the arms
// overhead 0.05 at best.
inline constexpr double kCloseRelief = 0.1;
inline constexpr double kWeakRelief = 0.3;
// Under this the canonical form is asked too, and takes the pose where it
// lays the relief better; a choice under it, by either, is warned of
// (population_doubts). Bodies bent the template's way agree 0.51 to
// 0.76 after the coarse fit. Of 25 bent the other way (bent-either, 6
// shapes of 2,500 vertices, seeds 1 to 8) the fit took the half turn for
// 11 at 0.33 to 0.44; the canonical form laid the relief better for 10 of
// them, in the true pose for 7 (0.46 to 0.59). FAUST's poses under it
// (0.43, 0.47) agree 0.09 and 0.11 canonically and keep their poses. Of
// the 25 bent the other way, 8 ended turned, chosen at margins up to 0.14.
inline constexpr double kSureRelief = 0.5;

// Two fits end in the same state where the template's vertices lie less
// than this apart on average (at unit area): then they are one pose, not a
// runner-up, however far apart they started.
inline constexpr double kSameEndState = 0.05;

struct ReliefChoice {
  std::size_t chosen = 0;  // into the poses given
  MeshAlignment::Relief relief{true};
};

// The template's side of the choice, the same for every shape: its
// vertices in the common frame, their surface_relief, and its coarse
// deformation graph there.
struct ReliefTemplate {
  ReliefTemplate(const SurfaceMesh& template_mesh, const PointSet& template_points);
  const SurfaceMesh& mesh;
  PointSet points;
  Eigen::VectorXd relief;
  DeformationGraph graph;
};

// `poses`: the shape's open poses, rigidly fitted (the fit's choice first).
// Ties keep the earlier pose.
ReliefChoice choose_pose_by_relief(const ReliefTemplate& reference, const SurfaceMesh& mesh,
                                   const std::vector<MeshAlignment>& poses);

}  // namespace meshparticles
