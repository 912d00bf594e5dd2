// correspondence/correspond_runner: `correspond` as one call. It refuses
// fewer than two meshes in one line; on three small shapes it writes the
// outputs (every shape's particles, the model, summary.json with the params
// asked), leaves no checkpoint behind, and a second run writes the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/user_error.hpp"
#include "correspondence/correspond_runner.hpp"
#include "correspondence/correspondence_checkpoint.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"
#include "test_folder.hpp"

namespace meshparticles::testing {
namespace {

class CorrespondRunner : public ::testing::Test {
 protected:
  void SetUp() override {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const std::filesystem::path file = directory_ / ("shape_" + std::to_string(seed) + ".off");
      write_mesh(generate_ellipsoid_variant(seed, 300).mesh, file);
      request_.inputs.push_back(file.string());
    }
    request_.out = directory_ / "out";
    request_.particles = 24;
    request_.refinement.iterations = 10;
    request_.samples = 20;
    request_.threads = 2;
    request_.quiet = true;
  }
  const TestFolder directory_{"mp_correspond_runner"};
  CorrespondRequest request_;
};

TEST_F(CorrespondRunner, FewerThanTwoMeshesAreRefusedInOneLine) {
  CorrespondRequest one = request_;
  one.inputs = {request_.inputs.front(), request_.inputs.front()};  // one file given twice counts once
  try {
    run_correspond(one);
    FAIL() << "one mesh was taken";
  } catch (const UserError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("correspond needs at least 2 meshes, got 1"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(request_.out));
}

TEST_F(CorrespondRunner, WritesTheOutputsItPromisesAndTheSameBytesAgain) {
  const std::optional<CorrespondOutcome> outcome = run_correspond(request_);
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->meshes, request_.inputs);
  EXPECT_GT(outcome->modes, 0u);
  EXPECT_EQ(outcome->compactness.size(), outcome->modes);
  EXPECT_GT(outcome->worst_fit, 0.0);

  std::ifstream summary_file(request_.out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary.at("params"), correspond_params(request_));
  EXPECT_EQ(summary.at("shapes").size(), 3u);
  EXPECT_EQ(summary.at("template").at("mesh"), request_.inputs.front());
  EXPECT_EQ(summary.at("refinement").at("overlap").size(), 10u);
  for (const char* stem : {"000_shape_1", "001_shape_2", "002_shape_3"}) {
    const std::string particles = text_of(request_.out / "shapes" / (std::string(stem) + ".particles"));
    EXPECT_EQ(std::count(particles.begin(), particles.end(), '\n'), 24) << stem;
    EXPECT_TRUE(std::filesystem::exists(request_.out / "shapes" / (std::string(stem) + ".csv"))) << stem;
  }
  EXPECT_TRUE(std::filesystem::exists(request_.out / "model" / "model.json"));
  EXPECT_FALSE(std::filesystem::exists(request_.out / CorrespondCheckpoint::kFolder));

  const std::string first = text_of(request_.out / "shapes" / "001_shape_2.particles");
  ASSERT_TRUE(run_correspond(request_));
  EXPECT_EQ(text_of(request_.out / "shapes" / "001_shape_2.particles"), first);
}

}  // namespace
}  // namespace meshparticles::testing
