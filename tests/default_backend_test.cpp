// The paper method's default backend follows the device and the size
// (docs/PERFORMANCE.md, "When the GPU pays"): on the table the CPU twin
// without a usable OpenCL device and below the size from which a GPU wins
// back its set-up, the field backend otherwise, monotone on both; on local
// distances the twin and its sequential loop.
#include <gtest/gtest.h>

#include "pipeline/default_backend.hpp"

namespace meshparticles::testing {
namespace {

DeviceDescription device_of_type(const std::string& type) {
  DeviceDescription device;
  device.name = "a " + type;
  device.type = type;
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
    EXPECT_EQ(chosen.reason.rfind("default: " + chosen.name, 0), 0u);
    if (c.device && c.store == StoreKind::dense) {
      EXPECT_NE(chosen.reason.find(c.device->name), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace meshparticles::testing
