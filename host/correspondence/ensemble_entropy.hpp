#pragma once
// The ensemble-entropy correspondence term (ShapeWorks' particle system):
// each shape pulled, in the population's aligned frame, down the gradient
// of the regularised ensemble entropy, log det(C + alpha I), C the
// covariance of the aligned shapes. It shrinks the shape-to-shape
// variation that few shapes share and leaves the true modes alone.
#include "correspondence/correspondence_term.hpp"

namespace meshparticles {

class EnsembleEntropy : public CorrespondenceTerm {
 public:
  CorrespondenceSteps steps(const std::vector<PointSet>& shapes, const std::vector<double>& spacings) const override;
};

}  // namespace meshparticles
