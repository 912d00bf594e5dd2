#include "correspondence/population_doubts.hpp"

#include <algorithm>
#include <cmath>

#include "common/text_format.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "mesh/mesh_topology.hpp"

namespace meshparticles {

namespace {

// Where the template's relief chose the pose (relief_pose): another pose
// that lays it almost as well (close_relief), none that lays it
// (weak_relief), or none surely (sure_relief). Elsewhere (the fit's choice,
// or a body's profile's, body_turn): a runner-up within open_pose_ratio.
std::string pose_doubt(const ShapeCorrespondence& shape, const PoseChoiceOptions& options) {
  const std::string name = shape.mesh.string() + ": ";
  const std::string turned = ": its particles may lie turned by that much";
  const MeshAlignment::Relief& relief = shape.alignment.relief;
  if (relief.measured) {
    const std::string where = relief.canonical ? " in canonical form" : "";
    if (relief.agreement < options.weak_relief) {
      return name + "the template's features agree with its own by " + format_number("%.2f", relief.agreement) +
             " at best" + where + " (fit_relief, under " + format_number("%.2f", options.weak_relief) +
             "): no pose tried lays them over each other, so its particles may lie turned or its limbs not followed";
    }
    if (relief.runner_up > relief.agreement - options.close_relief) {
      return name + "a pose " + format_number("%.0f", relief.runner_up_degrees) +
             " degrees from the one chosen lays the template's features over its own" + where +
             " almost as well (fit_relief: " +
             format_number("%.2f", relief.runner_up) + " against " + format_number("%.2f", relief.agreement) + ")" +
             turned;
    }
    if (relief.agreement < options.sure_relief) {
      // Neither the coarse fit nor the canonical form laid the features
      // surely: such choices on bent-either's small populations ended turned
      // 8 times in 25 at 2,500 vertices, 17 in 25 at 1,200.
      const std::string next = std::isfinite(relief.runner_up)
                                   ? "; a pose " + format_number("%.0f", relief.runner_up_degrees) + " degrees away " +
                                         format_number("%.2f", relief.runner_up)
                                   : "";
      return name + "no pose lays the template's features over its own surely" + where + " (fit_relief: " +
             format_number("%.2f", relief.agreement) + " at best, under " + format_number("%.2f", options.sure_relief) + next +
             "): its particles may lie turned";
    }
    return "";
  }
  const MeshAlignment::RunnerUp& runner_up = shape.alignment.runner_up;
  const double ratio = runner_up.rms_ratio;
  if (!(ratio < options.open_pose_ratio)) return "";
  return name + "a pose " + format_number("%.0f", runner_up.degrees) + " degrees from the one chosen fits the template " +
         (ratio < 0.9995 ? format_number("%.1f%% better", 100 * (1 - ratio))
                         : format_number("within %.1f%%", std::max(0.0, 100 * (ratio - 1)))) +
         " (fit_runner_up)" + turned;
}

}  // namespace

std::vector<std::string> population_doubts(const std::vector<ShapeCorrespondence>& shapes,
                                           const PoseChoiceOptions& options) {
  std::vector<std::string> doubts;
  if (shapes.empty()) return doubts;
  const MeshTopology& template_topology = shapes.front().topology;  // the template is shape 0
  for (const ShapeCorrespondence& shape : shapes) {
    if (shape.topology != template_topology) {
      doubts.push_back(shape.mesh.string() + " (" + describe(shape.topology) + ") is not of the template's topology (" +
                       describe(template_topology) +
                       "): its particles cannot match the template's everywhere, and the model's modes describe "
                       "the mismatch");
    }
    if (std::string pose = pose_doubt(shape, options); !pose.empty()) doubts.push_back(std::move(pose));
    // Two particles at one place: the shape's rows of the model hold a
    // duplicate, and somewhere else on it a hole.
    if (shape.quality.stacked > 0) {
      doubts.push_back(shape.mesh.string() + ": " + std::to_string(shape.quality.stacked) + " of its " +
                       std::to_string(shape.particles.rows()) +
                       " particles lie at another's place (quality.stacked in summary.json): the transfer folded "
                       "the template onto it there, and a hole is left elsewhere");
    }
  }
  return doubts;
}

}  // namespace meshparticles
