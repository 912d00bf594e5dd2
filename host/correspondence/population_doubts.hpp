#pragma once
// What a population's result cannot promise, a line per doubt naming the
// shape: a shape of another topology than the template's (shapes.front()),
// a pose another fits almost as well, particles stacked at one place. The
// caller prints them and writes them into summary.json's `warnings`. The
// pose's doubts are judged by the numbers that chose it (`options`).
#include <string>
#include <vector>

#include "correspondence/pose_choice_options.hpp"
#include "correspondence/shape_correspondence.hpp"

namespace meshparticles {

std::vector<std::string> population_doubts(const std::vector<ShapeCorrespondence>& shapes,
                                           const PoseChoiceOptions& options);

}  // namespace meshparticles
