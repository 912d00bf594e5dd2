// Long work stops when the process's interruption check says so (the Python
// module's Ctrl-C): Interrupted reaches the caller, the worker threads are
// joined first (a thread left joinable would end the process), and the
// work runs to the end again once the check is gone.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include <unistd.h>

#include <filesystem>

#include "batch/batch_runner.hpp"
#include "common/interruption.hpp"
#include "geodesics/distance_table.hpp"
#include "geodesics/local_distances.hpp"
#include "mesh/io/mesh_reader.hpp"

namespace meshparticles::testing {
namespace {

SurfaceMesh sphere() {
  std::vector<std::string> warnings;
  return read_mesh(std::string(MESHES_DIR) + "/sphere.off", warnings);
}

// Installs a check that always says stop, for one test.
struct AlwaysInterrupted {
  AlwaysInterrupted() { set_interruption_check([] { return true; }); }
  ~AlwaysInterrupted() { set_interruption_check(nullptr); }
};

TEST(Interruption, AllPairsOnTwoThreadsStopsAndJoinsItsWorkers) {
  const SurfaceMesh mesh = sphere();
  {
    const AlwaysInterrupted stop;
    EXPECT_THROW(compute_all_pairs(mesh, GeodesicMethod::fast_marching, 2, /*quiet=*/true), Interrupted);
  }
  const DistanceTable table = compute_all_pairs(mesh, GeodesicMethod::fast_marching, 2, /*quiet=*/true);
  EXPECT_GT(table.distance(0, VertexId(mesh.vertex_count() - 1)), 0.0f);
}

TEST(Interruption, BallsOnTwoThreadsStopAndKeepWhatWasSolved) {
  const SurfaceMesh mesh = sphere();
  LocalDistances::Settings settings;
  settings.radius = 0.3;
  settings.cache_bytes = std::uint64_t(1) << 30;
  settings.threads = 2;
  settings.quiet = true;
  const LocalDistances balls(mesh, settings);
  std::vector<VertexId> all(mesh.vertex_count());
  std::iota(all.begin(), all.end(), VertexId(0));
  {
    const AlwaysInterrupted stop;
    EXPECT_THROW(balls.prefetch(all), Interrupted);
  }
  balls.prefetch(all);
  EXPECT_EQ(balls.distance(7, 7), 0.0f);
}

// A batch stops as a whole: an interruption is no failure of one mesh.
TEST(Interruption, StopsAWholeBatchNotJustOneMesh) {
  const auto out = std::filesystem::temp_directory_path() / ("interrupted_batch_" + std::to_string(::getpid()));
  BatchRequest request;
  request.inputs = {std::string(MESHES_DIR) + "/torus.off", std::string(MESHES_DIR) + "/tetrahedron.off"};
  request.out = out;
  request.run.particles = 4;
  request.run.quiet = true;
  request.count.value = 4;
  request.quiet = true;
  {
    const AlwaysInterrupted stop;
    EXPECT_THROW(run_batch(request), Interrupted);
  }
  EXPECT_EQ(run_batch(request), 0);  // and runs to the end without the check
  std::filesystem::remove_all(out);
}

TEST(Interruption, WithoutACheckNothingStops) {
  set_interruption_check(nullptr);
  EXPECT_NO_THROW(throw_if_interrupted());
}

}  // namespace
}  // namespace meshparticles::testing
