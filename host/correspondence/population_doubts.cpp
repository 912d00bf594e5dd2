#include "correspondence/population_doubts.hpp"

#include <algorithm>

#include "common/text_format.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "mesh/mesh_topology.hpp"

namespace meshparticles {

namespace {

std::string pose_doubt(const ShapeCorrespondence& shape) {
  const MeshAlignment::RunnerUp& runner_up = shape.alignment.runner_up;
  const double population_ratio = shape.alignment.population_ratio;
  if (population_ratio > 0) {
    // The population chose among the poses the fit left open.
    if (population_ratio * kAmbiguousPoseRatio <= 1) return "";
    return shape.mesh.string() + ": a pose " + format_number("%.0f", runner_up.degrees) +
           " degrees from the one chosen is " +
           (population_ratio < 1 ? format_number("only %.1f%% farther from", 100 * (1 / population_ratio - 1))
                                 : format_number("%.1f%% nearer", 100 * (1 - 1 / population_ratio))) +
           " the other shapes: the population barely tells them apart, and its particles may lie turned "
           "(fit_population_ratio in summary.json)";
  }
  const double ratio = runner_up.rms_ratio;
  if (ratio >= kAmbiguousPoseRatio) return "";
  return shape.mesh.string() + ": a pose " + format_number("%.0f", runner_up.degrees) +
         " degrees from the one chosen fits the template " +
         (ratio < 0.9995 ? format_number("%.1f%% better", 100 * (1 - ratio))
                         : format_number("within %.1f%%", std::max(0.0, 100 * (ratio - 1)))) +
         ": the shape's geometry barely tells them apart, and its particles may lie turned (fit_runner_up in "
         "summary.json)";
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
