#pragma once
// What pulls the shapes' particles into correspondence in the joint
// refinement (joint_refinement): from every shape's particles, a step for
// each shape. Both the iterations and the packing call it, each with its own
// weight. A second term is a class of its own file beside ensemble_entropy,
// chosen in `correspondence_term` by an option of JointRefinementOptions.
#include <memory>
#include <vector>

#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

struct JointRefinementOptions;

struct CorrespondenceSteps {
  std::vector<PointSet> steps;  // per shape, in its own coordinates
  double mean_length = 0;       // the steps' mean length, in the aligned frame's spacings
};

class CorrespondenceTerm {
 public:
  virtual ~CorrespondenceTerm() = default;
  // `shapes`: every shape's particles (row i the same particle on each), in
  // its own coordinates; `spacings`: each shape's hexagonal spacing. The
  // same numbers in the same order give the same steps, on every process.
  virtual CorrespondenceSteps steps(const std::vector<PointSet>& shapes, const std::vector<double>& spacings) const = 0;
};

// The term `options` asks for.
std::unique_ptr<CorrespondenceTerm> correspondence_term(const JointRefinementOptions& options);

}  // namespace meshparticles
