#include "correspondence/correspondence_term.hpp"

#include "correspondence/ensemble_entropy.hpp"
#include "correspondence/joint_refinement.hpp"

namespace meshparticles {

std::unique_ptr<CorrespondenceTerm> correspondence_term(const JointRefinementOptions& options) {
  (void)options;  // one term so far: the choice among several goes here
  return std::make_unique<EnsembleEntropy>();
}

}  // namespace meshparticles
