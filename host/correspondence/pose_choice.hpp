#pragma once
// Which pose each shape of a population takes in the common frame (the
// template's canonical frame), chosen in one place by the numbers of one
// PoseChoiceOptions (pose_choice_options.hpp). In order:
//  1. its trials onto the template (mesh_alignment: the pose as given and
//     the 24 turns of its principal axes, each judged by a short affine
//     fit): the best, or the pose as given where it fits about as well;
//  2. where the trials leave several poses open (open_pose_ratio), the one
//     in which the template, bent onto the shape by a coarse deformation
//     graph, lays its relief over the shape's (relief_pose); where none
//     lays it surely (sure_relief), the pose of its canonical form
//     (canonical_pose), under weak_relief or where it lays it better, whose
//     pairs then guide the shape's deformation;
//  3. the medoid (the shape nearest the others) as a second reference: a
//     shape whose fit left one pose open, the template too, takes its pose
//     onto it where that lies clearly nearer the population
//     (nearer_population); one the relief or the canonical form chose keeps
//     it and follows the template;
//  4. where the template is an ellipsoid body, each shape with one takes
//     the turn of its body that the population's features agree on
//     (body_turn), and its stretch onto the template's radii.
// population_doubts warns by the same options. Every process chooses the
// same poses for the same shapes, whatever the number of processes and
// threads.
#include <optional>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_choice_options.hpp"
#include "correspondence/shape_share.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct PopulationPoses {
  // Every owned shape's pose (the others' default): MeshAlignment says how
  // it was chosen (`relief`, `runner_up`, `from_principal_axes`).
  std::vector<MeshAlignment> alignments;
  // Each template vertex's canonically nearest vertex of the shape, where
  // its canonical form chose its pose (else empty): they guide the
  // deformation graph's stiff stages.
  std::vector<std::vector<Eigen::Index>> guides;
};

// `meshes`: the template (first) and every owned shape, loaded;
// `template_points`: the template's vertices in the common frame (its
// canonical frame, `template_frame`), moved where the medoid moves the
// template. `quiet`: no progress line.
PopulationPoses choose_population_poses(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                                        const Similarity& template_frame, PointSet& template_points,
                                        const PoseChoiceOptions& options, bool quiet);

}  // namespace meshparticles
