// The parts of a batch that need no run: n from a density, the output
// folders' names, the order in which ranks are handed the meshes, and the
// meshes of a folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "batch/batch_plan.hpp"
#include "batch/mesh_queue.hpp"
#include "batch/output_names.hpp"
#include "batch/particle_count.hpp"
#include "common/user_error.hpp"
#include "launch/batch_inputs.hpp"

namespace meshparticles::testing {
namespace {

TEST(BatchParticleCount, FixedSpacingAndPerArea) {
  EXPECT_EQ(particles_for({ParticleCount::Rule::fixed, 64}, 10.0, 1000), 64u);
  // Hexagonal packing: one particle per sqrt(3)/2 H^2 of area.
  const double area = 4.0 * std::acos(-1.0);  // the unit sphere
  EXPECT_EQ(particles_for({ParticleCount::Rule::spacing, 0.2}, area, 4000),
            std::size_t(std::lround(2 * area / (std::sqrt(3.0) * 0.04))));
  EXPECT_EQ(particles_for({ParticleCount::Rule::per_area, 10}, 2.5, 1000), 25u);
  // Twice the area at the same density: twice the particles (within rounding).
  EXPECT_EQ(particles_for({ParticleCount::Rule::per_area, 10}, 5.0, 1000), 50u);
  // Clamped to [1, V]: every mesh gets a run.
  EXPECT_EQ(particles_for({ParticleCount::Rule::spacing, 1e-9}, area, 4000), 4000u);
  EXPECT_EQ(particles_for({ParticleCount::Rule::per_area, 1e-9}, area, 4000), 1u);
}

MeshInput input(const std::string& path, std::uintmax_t bytes = 0) {
  return {path, std::filesystem::path("/data") / path, bytes};
}

TEST(BatchOutputNames, SafeAndDistinct) {
  const auto names = output_names({input("a/heart 1!.off"), input(".hidden.ply"), input("x/lung.obj"),
                                   input("y/lung.stl"), input("summary.csv.off")});
  EXPECT_EQ(names[0], "heart_1_");
  EXPECT_EQ(names[1], "_hidden");
  // Two lungs: each named lung+ and 8 hex digits, different, never plain "lung".
  EXPECT_EQ(names[2].substr(0, 5), "lung+");
  EXPECT_EQ(names[2].size(), 13u);
  EXPECT_NE(names[2], names[3]);
  // A mesh never takes the summary's name.
  EXPECT_NE(names[4], "summary.csv");
  // The names depend on the inputs alone, not on their order.
  const auto swapped = output_names({input("y/lung.stl"), input("x/lung.obj")});
  EXPECT_EQ(swapped[0], names[3]);
  EXPECT_EQ(swapped[1], names[2]);
}

TEST(BatchOrder, BiggestFirstTiesInInputOrder) {
  BatchPlan plan;
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::uintmax_t>>{
           {"small.off", 10}, {"big.off", 300}, {"middle.off", 100}, {"big_too.off", 300}}) {
    plan.items.push_back({input(name, bytes), name});
  }
  EXPECT_EQ(biggest_first_order(plan), (std::vector<std::size_t>{1, 3, 2, 0}));
  EXPECT_EQ(input_order(plan), (std::vector<std::size_t>{0, 1, 2, 3}));
}

// A symlink loop named as a mesh is named and skipped, the rest run, wherever
// the listing meets it (last, it stopped batch and correspond with "cannot
// read folder ...: Too many levels of symbolic links"; otherwise it was
// dropped without a word); so is a link to nothing.
TEST(BatchInputs, FolderEntriesThatCannotBeReachedAreNamedAndSkipped) {
  const auto folder = std::filesystem::temp_directory_path() / ("mp_loop_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(std::string(MESHES_DIR) + "/tetrahedron.off", folder / "b.off");
  std::filesystem::create_symlink("a_loop.off", folder / "a_loop.off");
  std::filesystem::create_symlink("z_loop.off", folder / "z_loop.off");
  std::filesystem::create_symlink("missing.off", folder / "c_dangling.off");
  std::vector<std::string> notes;
  const std::vector<MeshInput> meshes = expand_batch_inputs({folder.string()}, notes);
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].path, folder / "b.off");
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0], (folder / "a_loop.off").string() + ": cannot read it (Too many levels of symbolic links): skipped");
  EXPECT_EQ(notes[1], (folder / "c_dangling.off").string() + ": a link to nothing: skipped");
  EXPECT_EQ(notes[2], (folder / "z_loop.off").string() + ": cannot read it (Too many levels of symbolic links): skipped");
  // With nothing else, the refusal says why.
  std::filesystem::remove(folder / "b.off");
  try {
    expand_batch_inputs({folder.string()}, notes);
    ADD_FAILURE() << "a folder of loops was taken";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("holds no mesh file (.off"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("a_loop.off: cannot read it"), std::string::npos) << error.what();
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace meshparticles::testing
