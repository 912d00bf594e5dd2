// The field backend's one-launch iterations (kernels/field_iterations.cl):
// whole runs make the serial twin's moves, energies and redone attempts at
// every work-group size the sweep tries, and the per-colour launches' too;
// they take at most one launch and one host wait per iteration; and a
// kernel that skips one of its barriers is caught.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "backends/field_backend.hpp"
#include "backends/serial_field_backend.hpp"
#include "particle_test_support.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"

namespace meshparticles::testing {
namespace {


// The twin computes the weights on the host (std::exp), the device with its
// own exp: a weight may differ in its last bit, so energies agree to 1e-7
// between the two and exactly between two device runs.
void expect_same_run(const RunOutcome& device, const RunOutcome& twin, bool exact_energy) {
  EXPECT_EQ(device.positions, twin.positions);
  EXPECT_EQ(device.converged, twin.converged);
  ASSERT_EQ(device.trace.size(), twin.trace.size());
  for (std::size_t i = 0; i < device.trace.size(); ++i) {
    EXPECT_EQ(device.trace[i].moved, twin.trace[i].moved) << "iteration " << i;
    if (exact_energy) {
      EXPECT_EQ(device.trace[i].energy, twin.trace[i].energy) << "iteration " << i;
    } else {
      EXPECT_NEAR(device.trace[i].energy, twin.trace[i].energy, 1e-7 * twin.trace[i].energy) << "iteration " << i;
    }
    EXPECT_EQ(device.trace[i].redone_as, twin.trace[i].redone_as) << "iteration " << i;
  }
}

struct Case {
  const char* mesh;
  std::size_t particles;
  Scheme scheme;
  unsigned colors;
  std::size_t iterations;
  bool redoes;  // the twin's run has monotone iterations that were undone and redone
};

// monotone with few colours redoes many iterations (undo, more colours, the
// sequential loop); colored K = 2 on the torus never settles, so a run
// spans many launches; the sphere at 1,024 is the paper's size.
const Case kCases[] = {
    {"torus.off", 200, Scheme::monotone, 2, 300, true},
    {"torus.off", 200, Scheme::colored, 2, 40, false},
    {"sphere.off", 1024, Scheme::monotone, kDefaultColors, 300, false},
    {"patch.off", 100, Scheme::monotone, 1, 300, true},
};

std::string describe(const Case& c) {
  return std::string(c.mesh) + " n " + std::to_string(c.particles) + " " + scheme_name(c.scheme) + " K " +
         std::to_string(c.colors);
}

TEST(OneLaunch, MakesTheSerialTwinsMovesAtEveryWorkGroupSize) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(describe(c));
    const MeshWithDistances m(c.mesh);
    const EnergyParams energy = m.default_energy(c.particles);
    const auto start = place_particles(m.mesh, {Init::random, c.particles, 3, std::nullopt});
    SerialFieldBackend twin_backend(m.mesh, m.distances, energy, WeightFormat::float32, 0);
    const RunOutcome twin = run(twin_backend, start, c.scheme, c.colors, c.iterations);
    std::size_t redone = 0;
    for (const auto& record : twin.trace) redone += !record.redone_as.empty();
    EXPECT_EQ(redone > 0, c.redoes) << "the case no longer exercises what it was chosen for";
    for (const std::size_t work_group : {1, 7, 32, 64, 256}) {
      SCOPED_TRACE("wg " + std::to_string(work_group));
      const auto device = device_backend(m, energy, "field", work_group);
      const RunOutcome outcome = run(*device, start, c.scheme, c.colors, c.iterations);
      expect_same_run(outcome, twin, false);
      // One launch and one read per kIterationsWithoutHost iterations, and
      // one more for an iteration limit or a settled run that cut one short.
      ASSERT_TRUE(outcome.traffic.has_value());
      const std::size_t launches = (outcome.trace.size() + kIterationsWithoutHost - 1) / kIterationsWithoutHost;
      EXPECT_EQ(outcome.traffic->launches, launches);
      EXPECT_EQ(outcome.traffic->host_waits, launches);
    }
  }
}

TEST(OneLaunch, MakesThePerColourLaunchesMoves) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::farthest, particles, 1, std::nullopt});
  const auto one_launch = device_backend(m, energy, "field", 32);
  const auto per_colour = device_backend(m, energy, "field", 32);
  dynamic_cast<FieldBackend&>(*per_colour).set_one_launch(false);
  const RunOutcome fused = run(*one_launch, start, Scheme::monotone, 2, 300);
  const RunOutcome launched = run(*per_colour, start, Scheme::monotone, 2, 300);
  expect_same_run(fused, launched, true);
  // Per colour: its update, commit and field update, then the energy's
  // launch and read: the traffic one launch removes.
  ASSERT_TRUE(launched.traffic && fused.traffic);
  EXPECT_GE(launched.traffic->launches, 3 * 2 * launched.trace.size());
  EXPECT_GE(launched.traffic->host_waits, launched.trace.size());
  EXPECT_LT(fused.traffic->launches, fused.trace.size());
}

// A copy of kernels/ in which field_iterations.cl lacks one barrier.
class WithoutBarrier {
 public:
  explicit WithoutBarrier(const std::string& barrier_line) {
    directory_ = std::filesystem::temp_directory_path() / ("meshparticles-barrier-" + std::to_string(getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
    for (const auto& entry : std::filesystem::directory_iterator(KERNELS_DIR)) {
      std::filesystem::copy_file(entry.path(), directory_ / entry.path().filename());
    }
    std::ifstream in(directory_ / "field_iterations.cl");
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    const std::size_t at = source.find(barrier_line);
    found_ = at != std::string::npos;
    if (found_) source.replace(at, barrier_line.size(), "// barrier skipped");
    std::ofstream(directory_ / "field_iterations.cl") << source;
    ::setenv("MESHPARTICLES_KERNEL_DIR", directory_.c_str(), 1);
  }
  ~WithoutBarrier() {
    ::unsetenv("MESHPARTICLES_KERNEL_DIR");
    std::filesystem::remove_all(directory_);
  }
  bool found() const { return found_; }

 private:
  std::filesystem::path directory_;
  bool found_ = false;
};

// The barriers inside a colour: without one, some work-item reads what
// another has not yet written (on PoCL, which runs a work-group's items one
// after another between barriers, deterministically so). The third, after
// F's update, PoCL cannot show missing: it puts a barrier of its own at the
// head of every loop that holds one, here the loop over colours.
TEST(OneLaunch, ASkippedBarrierIsCaught) {
  if (select_device("").platform_name.find("Portable Computing Language") == std::string::npos) {
    // On a GPU the race's outcome depends on how the device schedules the
    // work-group's warps: within one warp a missing barrier may never show.
    GTEST_SKIP() << "a missing barrier is caught deterministically only on PoCL (the suite's device in CI)";
  }
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::random, particles, 3, std::nullopt});
  SerialFieldBackend twin_backend(m.mesh, m.distances, energy, WeightFormat::float32, 0);
  const RunOutcome twin = run(twin_backend, start, Scheme::monotone, 2, 100);
  for (const std::string barrier : {"barrier(CLK_GLOBAL_MEM_FENCE);  // every choice made from the same snapshot",
                                    "barrier(CLK_GLOBAL_MEM_FENCE);  // the colour's moves listed and counted"}) {
    SCOPED_TRACE(barrier);
    const WithoutBarrier mutant(barrier);
    ASSERT_TRUE(mutant.found()) << "the test's edit no longer applies";
    const auto device = device_backend(m, energy, "field", 32);
    const RunOutcome outcome = run(*device, start, Scheme::monotone, 2, 100);
    bool same = outcome.positions == twin.positions && outcome.trace.size() == twin.trace.size();
    for (std::size_t i = 0; same && i < twin.trace.size(); ++i) {
      same = outcome.trace[i].moved == twin.trace[i].moved && outcome.trace[i].redone_as == twin.trace[i].redone_as;
    }
    EXPECT_FALSE(same) << "a run without this barrier made the twin's moves";
  }
}

}  // namespace
}  // namespace meshparticles::testing
