// Geodesic balls by the fast iterative method on the device (the
// fim_balls kernel) against the host's solver of the same method, and that
// method against fast marching: the same vertices in every ball and the
// same distances within float rounding, on the committed meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/user_error.hpp"
#include "geodesics/device_balls.hpp"
#include "geodesics/fast_iterative.hpp"
#include "geodesics/local_distances.hpp"
#include "fixtures/mesh_generator.hpp"
#include "particle_test_support.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {


// Every `stride`-th vertex.
std::vector<VertexId> every(const SurfaceMesh& mesh, std::size_t stride) {
  std::vector<VertexId> sources;
  for (VertexId v = 0; v < mesh.vertex_count(); v += VertexId(stride)) sources.push_back(v);
  return sources;
}

constexpr VertexId kPastTheEnd = std::numeric_limits<VertexId>::max();

// The device's ball against the host's: a vertex may be in one and not
// the other only where its distance is within rounding of the radius; the
// shared vertices' distances agree to float rounding.
struct BallAgreement {
  std::size_t shared = 0, only_one = 0;
  double sum_relative = 0, worst_relative = 0;
};

BallAgreement compare(const Ball& device, const Ball& host, double radius) {
  constexpr double kRounding = 1e-4;  // float against double, over some hundred rounds
  BallAgreement agreement;
  std::size_t i = 0, j = 0;
  while (i < device.vertices.size() || j < host.vertices.size()) {
    const VertexId dv = i < device.vertices.size() ? device.vertices[i] : kPastTheEnd;
    const VertexId hv = j < host.vertices.size() ? host.vertices[j] : kPastTheEnd;
    if (dv == hv) {
      const double d = device.distances[i++], h = host.distances[j++];
      const double relative = std::abs(d - h) / std::max(h, 1e-3 * radius);
      agreement.sum_relative += relative;
      agreement.worst_relative = std::max(agreement.worst_relative, relative);
      ++agreement.shared;
      continue;
    }
    const double d = dv < hv ? device.distances[i++] : host.distances[j++];
    EXPECT_GT(d, radius * (1 - kRounding)) << "a vertex well inside one ball only";
    ++agreement.only_one;
  }
  return agreement;
}

class DeviceBalls : public ::testing::TestWithParam<std::string> {};

TEST_P(DeviceBalls, AreTheHostMethodsBalls) {
  const SurfaceMesh mesh = committed(GetParam());
  const double radius = cutoff_radius(mesh, 1024);
  const FastIterativeMethod host(mesh);
  DeviceBallSolver device(mesh, host, select_device(""));
  const std::vector<VertexId> sources = every(mesh, std::max<std::size_t>(7, mesh.vertex_count() / 300));
  const std::vector<Ball> balls = device.solve_balls(sources, radius);
  ASSERT_EQ(balls.size(), sources.size());
  SolverScratch scratch;
  std::size_t shared = 0, only_one = 0;
  double sum = 0, worst = 0;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    ASSERT_TRUE(std::is_sorted(balls[k].vertices.begin(), balls[k].vertices.end()));
    const BallAgreement agreement = compare(balls[k], host.solve_ball(sources[k], radius, scratch), radius);
    shared += agreement.shared;
    only_one += agreement.only_one;
    sum += agreement.sum_relative;
    worst = std::max(worst, agreement.worst_relative);
  }
  std::printf("%s: %zu balls of %.0f vertices on average, %zu on the host; %zu vertices in one ball only; "
              "relative difference %.2e mean, %.2e largest\n",
              GetParam().c_str(), sources.size(), double(shared) / double(sources.size()),
              device.statistics().solved_on_host, only_one, sum / double(shared), worst);
  EXPECT_LT(sum / double(shared), 1e-5);
  EXPECT_LT(worst, 1e-2);
  EXPECT_LE(only_one, shared / 1000 + 1);
  EXPECT_EQ(device.statistics().solved_on_host, 0u) << "balls of 1,024 particles' cutoff fit the table";
}

INSTANTIATE_TEST_SUITE_P(CommittedMeshes, DeviceBalls,
                         ::testing::Values("sphere.off", "torus.off", "atrium.off", "two_pieces.off", "patch.off"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return mesh_stem(param.param); });

// On two threads, a few at a time, each told as it is done: every ball the
// host method's own, whatever thread solved it.
TEST(DeviceBalls, ABallPastTheTableIsSolvedOnTheHost) {
  const SurfaceMesh mesh = generate_mesh_at("sphere", 10000);
  const FastIterativeMethod host(mesh);
  DeviceBallSolver device(mesh, host, select_device(""), 2);
  ASSERT_LT(device.slots(), mesh.vertex_count());
  const std::vector<VertexId> sources{0, 17, 1234, 2000, 3001, 4002, 5003, 6004, 7005, 8006, 9007};
  const double radius = 10;  // the whole sphere
  std::vector<std::size_t> told;
  const std::vector<Ball> balls =
      device.solve_balls(sources, radius, [&](std::size_t done) { told.push_back(done); });
  EXPECT_EQ(device.statistics().solved_on_host, sources.size());
  ASSERT_GE(told.size(), 2u) << "told after the launch and after each few of the host's balls";
  EXPECT_TRUE(std::is_sorted(told.begin(), told.end()));
  EXPECT_EQ(told.back(), sources.size());
  SolverScratch scratch;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const Ball expected = host.solve_ball(sources[k], radius, scratch);
    EXPECT_EQ(balls[k].vertices, expected.vertices);
    EXPECT_EQ(balls[k].distances, expected.distances);
  }
}

// The local store with a device solves there every ball it is asked for:
// many at once (prefetch), a few, one alone (ball), and those its helpers
// take from request()'s queue; each is the host method's ball.
TEST(DeviceBalls, TheLocalStoreSolvesEveryBallOnTheDevice) {
  const SurfaceMesh mesh = committed("atrium.off");
  const double radius = cutoff_radius(mesh, 1024);
  LocalDistances::Settings settings{radius, GeodesicMethod::fast_iterative, std::uint64_t{1} << 30, 2, true,
                                    select_device("")};
  const LocalDistances store(mesh, settings);
  const std::vector<VertexId> many = every(mesh, 20), few{3, 5, 8}, queued{101, 202, 303, 404, 505, 606};
  store.prefetch(many);
  store.prefetch(few);
  store.request(queued);
  std::vector<VertexId> asked = many;
  asked.insert(asked.end(), few.begin(), few.end());
  asked.insert(asked.end(), queued.begin(), queued.end());
  asked.push_back(1);  // alone
  const FastIterativeMethod host(mesh);
  SolverScratch scratch;
  for (const VertexId v : asked) {
    const BallAgreement agreement = compare(*store.ball(v), host.solve_ball(v, radius, scratch), radius);
    EXPECT_LT(agreement.sum_relative / double(agreement.shared), 1e-5) << "vertex " << v;
    EXPECT_LE(agreement.only_one, agreement.shared / 100) << "vertex " << v;
  }
  const LocalDistances::Statistics statistics = store.statistics();
  EXPECT_GE(statistics.balls_computed, many.size() + few.size() + queued.size() + 1);
  EXPECT_EQ(statistics.balls_on_device, statistics.balls_computed);
}

// A device without the memory for the mesh's buffers is refused before
// anything is built or uploaded, saying what it needs and what it has.
TEST(DeviceBalls, ADeviceWithoutTheMemoryIsRefusedFirst) {
  const SurfaceMesh mesh = committed("sphere.off");
  const FastIterativeMethod host(mesh);
  DeviceDescription small = select_device("");
  small.global_memory_bytes = std::uint64_t{1} << 20;
  try {
    DeviceBallSolver device(mesh, host, small);
    FAIL() << "a 1 MiB device was accepted";
  } catch (const UserError& refusal) {
    EXPECT_NE(std::string(refusal.what()).find("it has 1 MiB"), std::string::npos) << refusal.what();
  }
}

// The plan's check from the vertex count alone (spread's measurement with
// --device): the same refusal, before the mesh is built; a real device
// takes a 200k-vertex mesh's.
TEST(DeviceBalls, ThePlansCheckRefusesADeviceWithoutTheMemory) {
  DeviceDescription small = select_device("");
  EXPECT_NO_THROW(check_device_balls_fit(small, 200000));
  small.global_memory_bytes = std::uint64_t{1} << 20;
  try {
    check_device_balls_fit(small, committed("sphere.off").vertex_count());
    FAIL() << "a 1 MiB device was accepted";
  } catch (const UserError& refusal) {
    const std::string message = refusal.what();
    EXPECT_NE(message.find("it has 1 MiB"), std::string::npos) << message;
    EXPECT_NE(message.find(small.name), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace meshparticles::testing
