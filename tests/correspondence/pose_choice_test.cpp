// correspondence/pose_choice: a population's poses chosen in one place, by
// the numbers of one PoseChoiceOptions: the options it is given are the
// ones its mechanisms read, and its choice is the same on any number of
// threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_choice.hpp"
#include "correspondence/shape_share.hpp"
#include "fixtures/bent_body.hpp"

namespace meshparticles::testing {
namespace {

// Three bent bodies, each posed at random: the half turn of each fits
// within 1.03 to 1.09 of its right pose (PoseChoiceOptions::open_pose_ratio).
std::vector<std::optional<SurfaceMesh>> bent_population() {
  std::vector<std::optional<SurfaceMesh>> meshes;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) meshes.emplace_back(generate_bent_body(seed, 1200).mesh);
  return meshes;
}

PopulationPoses poses_of(const std::vector<std::optional<SurfaceMesh>>& meshes, const PoseChoiceOptions& options,
                         unsigned threads) {
  ShapeShare share(meshes.size(), threads);
  const Similarity template_frame = canonical_frame(*meshes.front());
  PointSet template_points = template_frame.apply(vertex_points(*meshes.front()));
  return choose_population_poses(meshes, share, template_frame, template_points, options, true);
}

// Whether each shape's own trials leave more than one pose open under
// `options` (the template's own pose is its frame's).
std::vector<bool> open_poses(const std::vector<std::optional<SurfaceMesh>>& meshes, const PoseChoiceOptions& options) {
  const Similarity template_frame = canonical_frame(*meshes.front());
  const PointSet template_points = template_frame.apply(vertex_points(*meshes.front()));
  const PointsTree tree(template_points);
  std::vector<bool> open(meshes.size(), false);
  for (std::size_t k = 1; k < meshes.size(); ++k) {
    open[k] = pose_trials(*meshes[k], template_points, template_frame, tree, options).distinct_poses(options).size() > 1;
  }
  return open;
}

// The relief chooses a shape's pose exactly where the trials, by the
// options given, leave it more than one: by default the half turn of some
// bent bodies; where the options leave no other pose open, none.
TEST(PoseChoice, TheOptionsGivenAreTheOnesTheTrialsRead) {
  const std::vector<std::optional<SurfaceMesh>> meshes = bent_population();
  PoseChoiceOptions one_pose;
  one_pose.open_pose_ratio = 1;
  std::size_t relief_chosen = 0;
  for (const PoseChoiceOptions& options : {PoseChoiceOptions{}, one_pose}) {
    const PopulationPoses poses = poses_of(meshes, options, 1);
    const std::vector<bool> open = open_poses(meshes, options);
    for (std::size_t k = 0; k < meshes.size(); ++k) {
      EXPECT_EQ(poses.alignments[k].relief.measured, open[k]) << "shape " << k << ", ratio " << options.open_pose_ratio;
      relief_chosen += poses.alignments[k].relief.measured;
      if (!open[k]) {
        EXPECT_TRUE(poses.guides[k].empty()) << "shape " << k;
      }
    }
    if (options.open_pose_ratio == 1) {
      EXPECT_EQ(std::count(open.begin(), open.end(), true), 0);
    }
  }
  EXPECT_GT(relief_chosen, 0u);  // the defaults leave some half turn open
}

// Each owner decides its own shapes: two threads choose the same poses, to
// the bit, as one.
TEST(PoseChoice, TheSamePosesOnAnyNumberOfThreads) {
  const std::vector<std::optional<SurfaceMesh>> meshes = bent_population();
  const PopulationPoses one = poses_of(meshes, {}, 1), two = poses_of(meshes, {}, 2);
  ASSERT_EQ(one.alignments.size(), meshes.size());
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    const Similarity &a = one.alignments[k].to_common, &b = two.alignments[k].to_common;
    EXPECT_EQ(a.scale, b.scale) << "shape " << k;
    EXPECT_EQ(a.rotation, b.rotation) << "shape " << k;
    EXPECT_EQ(a.translation, b.translation) << "shape " << k;
    EXPECT_EQ(one.alignments[k].relief.agreement, two.alignments[k].relief.agreement) << "shape " << k;
    EXPECT_EQ(one.guides[k], two.guides[k]) << "shape " << k;
  }
}

}  // namespace
}  // namespace meshparticles::testing
