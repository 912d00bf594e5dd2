// correspondence/correspond_request: correspond_params names every
// parameter that changes a result, and the checkpoint's fingerprint follows
// each of them, less those only the model reads, and the inputs' files.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "common/version.hpp"
#include "correspondence/correspond_request.hpp"

namespace meshparticles::testing {
namespace {

TEST(CorrespondRequest, ParamsHoldWhatWasAsked) {
  CorrespondRequest request;
  request.particles = 96;
  request.seed = 7;
  request.scale = false;
  request.samples = 20;
  request.refinement.iterations = 30;
  request.refinement.correspondence_weight = 0.25;
  request.refinement.pack = false;
  request.refinement.packing_hold = 0.5;
  request.refinement.even_enough = 0.6;
  request.deformation = TemplateDeformation::smooth;
  const nlohmann::json params = correspond_params(request);
  EXPECT_EQ(params.at("particles"), 96);
  EXPECT_EQ(params.at("seed"), 7);
  EXPECT_EQ(params.at("scale"), false);
  EXPECT_EQ(params.at("samples"), 20);
  EXPECT_EQ(params.at("refine_iterations"), 30);
  EXPECT_EQ(params.at("correspondence_weight"), 0.25);
  EXPECT_EQ(params.at("packing"), false);
  EXPECT_EQ(params.at("packing_hold"), 0.5);
  EXPECT_EQ(params.at("even_enough"), 0.6);
  EXPECT_EQ(params.at("deformation"), "smooth");
  EXPECT_EQ(params.size(), 10u) << params.dump();
}

// Each parameter of a stage changes the fingerprint (a stale checkpoint
// would otherwise resume silently); the model's alone do not.
TEST(CorrespondRequest, TheFingerprintFollowsEveryParameterButTheModelsOwn) {
  const CorrespondRequest base;
  const std::vector<std::string> meshes;
  const nlohmann::json fingerprint = checkpoint_fingerprint(base, meshes);
  EXPECT_EQ(fingerprint.at("version"), program_version());
  EXPECT_FALSE(fingerprint.contains("scale"));
  EXPECT_FALSE(fingerprint.contains("samples"));
  const std::vector<std::function<void(CorrespondRequest&)>> stage_changes{
      [](CorrespondRequest& r) { r.particles = 100; },
      [](CorrespondRequest& r) { r.seed = 2; },
      [](CorrespondRequest& r) { r.refinement.iterations = 1; },
      [](CorrespondRequest& r) { r.refinement.correspondence_weight = 0.2; },
      [](CorrespondRequest& r) { r.refinement.pack = false; },
      [](CorrespondRequest& r) { r.refinement.packing_hold = 0.3; },
      [](CorrespondRequest& r) { r.refinement.even_enough = 0.9; },
      [](CorrespondRequest& r) { r.deformation = TemplateDeformation::smooth; }};
  for (std::size_t k = 0; k < stage_changes.size(); ++k) {
    CorrespondRequest changed = base;
    stage_changes[k](changed);
    EXPECT_NE(checkpoint_fingerprint(changed, meshes), fingerprint) << "change " << k;
  }
  CorrespondRequest model_only = base;
  model_only.scale = false;
  model_only.samples = 5;
  model_only.threads = 3;
  model_only.quiet = true;
  EXPECT_EQ(checkpoint_fingerprint(model_only, meshes), fingerprint);
  EXPECT_NE(correspond_params(model_only), correspond_params(base));
}

// The inputs by path, size and time: the same file rewritten at another
// size is another run; a file that is not there still gives a fingerprint.
TEST(CorrespondRequest, TheFingerprintFollowsTheInputFiles) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("mp_fingerprint_" + std::to_string(::getpid()) + ".off");
  std::ofstream(file) << "OFF\n";
  const CorrespondRequest request;
  const nlohmann::json before = checkpoint_fingerprint(request, {file.string()});
  EXPECT_EQ(before.at("inputs").size(), 1u);
  EXPECT_EQ(before.at("inputs")[0][0], file.string());
  EXPECT_EQ(before.at("inputs")[0][1], 4);
  EXPECT_EQ(checkpoint_fingerprint(request, {file.string()}), before);
  std::ofstream(file) << "OFF\n0 0 0\n";
  EXPECT_NE(checkpoint_fingerprint(request, {file.string()}), before);
  std::filesystem::remove(file);
  const nlohmann::json gone = checkpoint_fingerprint(request, {file.string()});
  EXPECT_EQ(gone.at("inputs")[0][1], 0);
  EXPECT_NE(checkpoint_fingerprint(request, {file.string(), file.string()}), gone);
}

}  // namespace
}  // namespace meshparticles::testing
