// The paper method's default backend follows the device and the size
// (docs/PERFORMANCE.md, "When the GPU pays"): on the table the CPU twin
// without a usable OpenCL device and below the size from which a GPU wins
// back its set-up, the field backend otherwise, monotone on both; on local
// distances the twin and its sequential loop, but on a GPU from the mesh
// size at which it pays, where a ball fits the device's table: then field,
// the balls by fim on the GPU.
#include <gtest/gtest.h>

#include "geodesics/device_balls.hpp"
#include "pipeline/default_backend.hpp"

namespace meshparticles::testing {
namespace {

DeviceDescription device_of_type(const std::string& type) {
  DeviceDescription device;
  device.name = "a " + type;
  device.type = type;
  device.local_memory_bytes = 48 << 10;  // a table of 4,096 vertices
  return device;
}

TEST(DefaultBackend, FollowsTheDeviceAndTheSize) {
  const DeviceDescription gpu = device_of_type("GPU"), cpu = device_of_type("CPU");
  struct Case {
    StoreKind store;
    std::size_t particles;
    const DeviceDescription* device;
    const char* expected;
  };
  const Case cases[] = {
      {StoreKind::dense, 1024, nullptr, "serial-field"},
      {StoreKind::local, 100000, nullptr, "serial-field"},
      {StoreKind::dense, 64, &cpu, "field"},
      {StoreKind::local, 100000, &cpu, "serial-field"},
      {StoreKind::dense, kGpuPaysFromParticlesDense - 1, &gpu, "serial-field"},
      {StoreKind::dense, kGpuPaysFromParticlesDense, &gpu, "field"},
      {StoreKind::local, 100000, &gpu, "serial-field"},
  };
  for (const Case& c : cases) {
    const DefaultBackend chosen = default_paper_backend(c.store, c.particles, c.device);
    SCOPED_TRACE(chosen.reason);
    EXPECT_EQ(chosen.name, c.expected) << c.particles << " particles";
    EXPECT_EQ(chosen.scheme, c.store == StoreKind::dense ? Scheme::monotone : Scheme::sequential);
    EXPECT_FALSE(chosen.geodesic) << "the solver is the user's below the local rule's sizes";
    EXPECT_EQ(chosen.reason.rfind("default: " + chosen.name, 0), 0u);
    if (c.device && c.store == StoreKind::dense) {
      EXPECT_NE(chosen.reason.find(c.device->name), std::string::npos);
    }
  }
}

TEST(DefaultBackend, OnLocalBallsAGpuTakesLargeMeshesWhoseBallsFitItsTable) {
  const DeviceDescription gpu = device_of_type("GPU"), cpu = device_of_type("CPU");
  const std::size_t large = kGpuPaysFromVerticesLocal, small = kGpuPaysFromVerticesLocal - 1;
  const std::size_t slots = device_ball_slots(gpu);
  ASSERT_EQ(slots, 4096u);
  struct Case {
    LocalBalls balls;
    const DeviceDescription* device;
    const char* expected;
    const char* because;
  };
  const double fits = 1800, too_big = 2100;
  const Case cases[] = {
      {{large, fits, std::nullopt}, &gpu, "field", "the GPU"},
      {{large, fits, GeodesicMethod::fast_iterative}, &gpu, "field", "the GPU"},
      {{small, fits, std::nullopt}, &gpu, "serial-field", "below the"},
      {{large, too_big, std::nullopt}, &gpu, "serial-field", "holds with their margin"},
      {{large, fits, GeodesicMethod::fast_marching}, &gpu, "serial-field", "--geodesic"},
      {{large, fits, std::nullopt}, &cpu, "serial-field", "no GPU"},
      {{large, fits, std::nullopt}, nullptr, "serial-field", "no GPU"},
  };
  for (const Case& c : cases) {
    const DefaultBackend chosen = default_paper_backend(StoreKind::local, 100000, c.device, c.balls);
    SCOPED_TRACE(chosen.reason);
    EXPECT_EQ(chosen.name, c.expected);
    EXPECT_NE(chosen.reason.find(c.because), std::string::npos);
    const bool gpu_takes_balls = chosen.name == "field";
    EXPECT_EQ(chosen.scheme, gpu_takes_balls ? Scheme::monotone : Scheme::sequential);
    EXPECT_EQ(chosen.geodesic, gpu_takes_balls ? std::optional(GeodesicMethod::fast_iterative) : std::nullopt);
  }
  EXPECT_TRUE(local_default_may_use_device({large, fits, std::nullopt}));
  EXPECT_FALSE(local_default_may_use_device({small, fits, std::nullopt}));
  EXPECT_FALSE(local_default_may_use_device({large, fits, GeodesicMethod::dijkstra}));
}

}  // namespace
}  // namespace meshparticles::testing
