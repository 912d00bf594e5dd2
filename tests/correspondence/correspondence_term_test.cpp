// correspondence/correspondence_term: the term JointRefinementOptions asks
// for. One term so far: every option gives the ensemble entropy, and its
// steps are EnsembleEntropy's own.
#include <gtest/gtest.h>

#include <memory>
#include <typeinfo>
#include <vector>

#include "correspondence/correspondence_term.hpp"
#include "correspondence/ensemble_entropy.hpp"
#include "correspondence/joint_refinement.hpp"

namespace meshparticles::testing {
namespace {

TEST(CorrespondenceTerm, TheOptionsChooseTheEnsembleEntropy) {
  JointRefinementOptions options;
  const std::unique_ptr<CorrespondenceTerm> term = correspondence_term(options);
  ASSERT_TRUE(term);
  const CorrespondenceTerm& chosen = *term;  // a name: typeid of *term reads as a call with side effects to clang
  EXPECT_EQ(typeid(chosen), typeid(EnsembleEntropy));
  options.correspondence_weight = 0;
  options.pack = false;
  const std::unique_ptr<CorrespondenceTerm> other = correspondence_term(options);
  const CorrespondenceTerm& chosen_without_packing = *other;
  EXPECT_EQ(typeid(chosen_without_packing), typeid(EnsembleEntropy));

  const PointSet base = PointSet::Random(12, 3);
  std::vector<PointSet> shapes{base, base * 1.1 + PointSet::Random(12, 3) * 0.05, base * 0.9};
  const std::vector<double> spacings{0.3, 0.33, 0.27};
  const CorrespondenceSteps through_term = term->steps(shapes, spacings);
  const CorrespondenceSteps direct = EnsembleEntropy().steps(shapes, spacings);
  ASSERT_EQ(through_term.steps.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(through_term.steps[k], direct.steps[k]);
  EXPECT_EQ(through_term.mean_length, direct.mean_length);
}

}  // namespace
}  // namespace meshparticles::testing
