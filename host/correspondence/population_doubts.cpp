#include "correspondence/population_doubts.hpp"

#include <algorithm>

#include "common/text_format.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "mesh/mesh_topology.hpp"

namespace meshparticles {

namespace {

// Where the shape's own fit left another pose open (kOpenPoseRatio): the
// runner-up's margin, and the population's where it chose.
std::string pose_doubt(const ShapeCorrespondence& shape) {
  const MeshAlignment::RunnerUp& runner_up = shape.alignment.runner_up;
  const double ratio = runner_up.rms_ratio;
  if (!(ratio < kOpenPoseRatio)) return "";
  const double population_ratio = shape.alignment.population_ratio;
  const std::string chosen_by =
      population_ratio <= 0 ? ""
      : population_ratio < 1
          ? "; the other shapes prefer the pose chosen by only " +
                format_number("%.1f%%", 100 * (1 / population_ratio - 1)) + " (fit_population_ratio)"
          : "; the other shapes lie " + format_number("%.1f%%", 100 * (1 - 1 / population_ratio)) +
                " nearer the other pose (fit_population_ratio)";
  return shape.mesh.string() + ": a pose " + format_number("%.0f", runner_up.degrees) +
         " degrees from the one chosen fits the template " +
         (ratio < 0.9995 ? format_number("%.1f%% better", 100 * (1 - ratio))
                         : format_number("within %.1f%%", std::max(0.0, 100 * (ratio - 1)))) +
         " (fit_runner_up)" + chosen_by + ": its particles may lie turned by that much";
}

}  // namespace

std::vector<std::string> population_doubts(const std::vector<ShapeCorrespondence>& shapes) {
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
    if (std::string pose = pose_doubt(shape); !pose.empty()) doubts.push_back(std::move(pose));
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
