// The progress line's quiet cases on a file or pipe (where a test's stderr
// goes): only the final summary is written, and not even that for work
// finished before `shown_after` seconds.
#include <gtest/gtest.h>

#include <string>

#include "common/progress.hpp"

namespace meshparticles {
namespace {

std::string summary_of(double shown_after) {
  ::testing::internal::CaptureStderr();
  ProgressLine progress("balls", 10, false, shown_after);
  progress.update(10);
  progress.finish();
  return ::testing::internal::GetCapturedStderr();
}

TEST(ProgressLine, SummarisesWorkOnAFile) {
  EXPECT_NE(summary_of(0).find("balls: 10 done in"), std::string::npos);
}

TEST(ProgressLine, WorkQuickerThanShownAfterLeavesNothing) {
  EXPECT_EQ(summary_of(60), "");
}

TEST(ProgressLine, QuietLeavesNothing) {
  ::testing::internal::CaptureStderr();
  ProgressLine progress("balls", 10, true);
  progress.finish();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace meshparticles
