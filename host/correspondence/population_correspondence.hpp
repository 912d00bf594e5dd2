#pragma once
// Particles that correspond across a population (issue 31): the template
// (the first shape) is sampled by the default run (spread); every shape is
// brought into the template's frame (pose_choice: its fit onto the template,
// the relief's or canonical form's choice among the poses the fit leaves
// open, the medoid, the body's turn) and the template is deformed
// onto it (deformation_graph, or template_deformation); each template
// particle goes to the nearest point of each shape's surface, so particle i
// sits at the same place, up to how well the shapes fit, on every shape;
// particles left where their geodesic distances to the others do not hold
// are put back (geodesic_repair); then every shape's particles are refined
// together (joint_refinement): each shape evened out while the
// correspondence holds. docs/CORRESPONDENCE.md.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "correspondence/correspondence_checkpoint.hpp"
#include "correspondence/joint_refinement.hpp"
#include "correspondence/pose_choice_options.hpp"
#include "correspondence/shape_correspondence.hpp"
#include "correspondence/shape_share.hpp"
#include "correspondence/template_deformation.hpp"
#include "quality/distribution_quality.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// The template's spread run works on a finer mesh than `run`'s own default
// (midpoint rounds to 24 vertices a particle, then no edge over 0.5
// spacings: `run`'s before 0.11) where the request leaves it open. On the
// coarser one (no rounds, edges over 0.3 spacings) the template's particles
// differ a little, and on FAUST's people at n = 256 that alone left a shape
// with a close pair: seed 1, the packing kept by a hair (the median shape's
// smallest spacing 0.4088 against 0.4080) and two arms' sides squeezed
// together at an armpit, where the packing does not push pairs that face
// apart (rho 0.20); seed 3, a pair the iterations left at a fingertip
// (rho 0.33). On this mesh, rho 0.59 to 0.62 on seeds 1 to 3.
// docs/CORRESPONDENCE.md, step 1 and "Tried and dropped".
inline constexpr double kTemplateVerticesPerParticle = 24;
inline constexpr double kTemplateLongestEdge = 0.5;

struct PopulationRequest {
  std::vector<std::filesystem::path> meshes;  // the first is the template
  RunRequest run;                             // the template's run (-n, seed, method, ...)
  JointRefinementOptions refinement;
  TemplateDeformation deformation = TemplateDeformation::graph;
  // How each shape's pose is chosen and its doubts judged: the measured
  // numbers, no option of correspond's (so not in correspond_params).
  PoseChoiceOptions poses;
  bool quiet = false;
};

struct PopulationCorrespondence {
  DistributionQuality template_quality;  // its own run's (on the leader)
  // What the result cannot promise, a line each (on stderr too):
  // population_doubts.
  std::vector<std::string> warnings;
  std::vector<ShapeCorrespondence> shapes;
  JointRefinementRecord refinement;
};

// Every shape's result, on every process of `share` (each process loads,
// fits and moves its own shapes). With a `checkpoint`, each stage finished
// is kept there, and a stage kept by an earlier run of the same request is
// taken from it instead of done again: the result is the same to the bit.
// Throws UserError for a mesh that cannot be read (naming it), and for -n
// above the template's vertices.
PopulationCorrespondence correspond_population(const PopulationRequest& request, ShapeShare& share,
                                               const CorrespondCheckpoint* checkpoint);
// One process, all cores, no checkpoint.
PopulationCorrespondence correspond_population(const PopulationRequest& request);

}  // namespace meshparticles
