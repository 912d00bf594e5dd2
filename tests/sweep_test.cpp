// The sweep's promises: sizes over the device's limits are skipped with the
// reason, a kernel that disagrees with the serial reference is FAILED and
// never timed, the rest are timed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "backends/backend_table.hpp"
#include "particle_test_support.hpp"
#include "particles/initial_placement.hpp"
#include "measurement/sweep.hpp"

namespace meshparticles::testing {
namespace {

UpdateKernel sizes(const std::string& kind, std::size_t wg, std::size_t tile, const SurfaceMesh& mesh) {
  UpdateKernel kernel;
  kernel.backend = &find_backend(kind);
  kernel.work_group_size = wg;
  kernel.tile_size = tile;
  kernel.candidate_slots = mesh.max_valence() + 1;
  return kernel;
}

TEST(SweepConfigurations, NaiveTakesNoTiles) {
  const auto configurations =
      sweep_configurations({"naive", "tiled", "naive"}, {8, 64, 8}, {16, 32, 64}, 7, WeightFormat::half);
  ASSERT_EQ(configurations.size(), 2u + 6u) << "each kernel and size once";
  EXPECT_EQ(configurations[0].name(), "naive");
  EXPECT_EQ(configurations[0].weights, WeightFormat::float32) << "naive takes no weight format";
  EXPECT_EQ(configurations[2].name(), "tiled");
  EXPECT_EQ(configurations[2].tile_size, 16u);
  EXPECT_EQ(configurations.back().work_group_size, 64u);
  EXPECT_EQ(configurations.back().tile_size, 64u);
}

class SweepTest : public ::testing::Test {
 protected:
  MeshWithDistances m{"torus.off"};
  EnergyParams energy = m.default_energy(200);
  std::vector<VertexId> positions = place_particles(m.mesh, {Init::random, 200, 3, std::nullopt});
  SweepSettings settings{Scheme::colored, 4, 3, 1, true};
};

TEST_F(SweepTest, TimesValidSizesAndSkipsRefusedOnes) {
  const DeviceDescription device = select_device("");
  const std::vector<UpdateKernel> configurations = {
      sizes("naive", 8, 0, m.mesh), sizes("tiled", 32, 16, m.mesh),
      sizes("tiled", device.max_work_group_size + 1, 16, m.mesh),
      sizes("tiled", 8, device.local_memory_bytes, m.mesh)};
  const auto results = measure_configurations(device, m.mesh, m.distances, energy, positions, configurations, settings);
  ASSERT_EQ(results.size(), 4u);
  for (int k : {0, 1}) {
    EXPECT_EQ(results[k].status, SweepStatus::ok) << results[k].reason;
    EXPECT_GT(results[k].timing.min_ms, 0.0);
    EXPECT_LE(results[k].timing.min_ms, results[k].timing.median_ms);
  }
  EXPECT_EQ(results[2].status, SweepStatus::skipped);
  EXPECT_NE(results[2].reason.find("maximum work-group size"), std::string::npos) << results[2].reason;
  EXPECT_EQ(results[3].status, SweepStatus::skipped);
  EXPECT_NE(results[3].reason.find("local memory"), std::string::npos) << results[3].reason;
  EXPECT_EQ(best_result(results, "tiled"), &results[1]);
}

// A tiled kernel that takes each particle's second-best candidate.
TEST_F(SweepTest, AWrongKernelIsFailedAndNotTimed) {
  const auto directory = std::filesystem::temp_directory_path() / ("meshparticles-wrong-" + std::to_string(getpid()));
  std::filesystem::create_directories(directory);
  for (const auto& entry : std::filesystem::directory_iterator(KERNELS_DIR)) {
    std::filesystem::copy_file(entry.path(), directory / entry.path().filename());
  }
  std::ifstream in(directory / "tiled_update.cl");
  std::stringstream text;
  text << in.rdbuf();
  std::string source = text.str();
  const std::string rank = "stack_rank[q]));";
  ASSERT_NE(source.find(rank), std::string::npos) << "the test's edit no longer applies";
  source.replace(source.find(rank), rank.size(), "stack_rank[q] + 1));");
  std::ofstream(directory / "tiled_update.cl") << source;

  ::setenv("MESHPARTICLES_KERNEL_DIR", directory.c_str(), 1);
  const auto results = measure_configurations(select_device(""), m.mesh, m.distances, energy, positions,
                                 {sizes("naive", 8, 0, m.mesh), sizes("tiled", 16, 32, m.mesh)},
                                 settings);
  ::unsetenv("MESHPARTICLES_KERNEL_DIR");
  std::filesystem::remove_all(directory);

  EXPECT_EQ(results[0].status, SweepStatus::ok);
  EXPECT_EQ(results[1].status, SweepStatus::failed);
  EXPECT_NE(results[1].reason.find("differ from the serial reference"), std::string::npos) << results[1].reason;
  EXPECT_EQ(results[1].timing.median_ms, 0.0) << "a failed configuration must not be timed";
  EXPECT_EQ(best_result(results, "tiled"), nullptr);
}

}  // namespace
}  // namespace meshparticles::testing
