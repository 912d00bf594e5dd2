#pragma once
// What a population's result cannot promise, a line per doubt naming the
// shape: a shape of another topology than the template's (shapes.front()),
// a pose another fits almost as well, particles stacked at one place. The
// caller prints them and writes them into summary.json's `warnings`.
#include <string>
#include <vector>

#include "correspondence/shape_correspondence.hpp"

namespace meshparticles {

std::vector<std::string> population_doubts(const std::vector<ShapeCorrespondence>& shapes);

}  // namespace meshparticles
