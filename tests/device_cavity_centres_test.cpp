// The evening's moves on the device (particles/device_cavity_centres over
// kernels/cavity_centres.cl) against the host's (particles/cavity_centre):
// one code (kernels/cavity_centre.h) in double, built for the device
// without unsafe math and with FP_CONTRACT off, so every move is the
// host's to the bit, and so is every particle of the whole evening,
// sweeps and swaps: on the committed meshes and on CGAL models at 64,
// 1,024 and 4,096 particles (measured; the suite runs a subset). The
// diagrams are the host's in both, so that only the moves differ in where
// they ran.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

#include "common/user_error.hpp"
#include "evening_start.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/device_cavity_centres.hpp"
#include "particles/local_farthest_points.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {

EveningOutcome evening_with_moves_on(const SurfaceMesh& mesh, const EveningStart& s, DeviceCavityCentres* moves) {
  const double d_hex = s.d_hex;
  // Swaps below 0.95 spacings, two rounds at most: spread's own limits
  // would swap only where the sweeps stall below 0.9.
  const EveningLimits limits{40, d_hex, 1e-3 * d_hex, 1e-4 * d_hex, 1.1 * s.start_cover, 0.95 * d_hex, 2, true};
  return even_out(mesh, *s.solver, s.from, limits, 2, true, {nullptr, moves});
}

// The evening's particles with the moves on `device` the host's to the
// bit; what it took, printed.
void expect_the_hosts_moves(const SurfaceMesh& mesh, const std::string& name, std::size_t n,
                            const DeviceDescription& device) {
  SCOPED_TRACE(name + ", n = " + std::to_string(n));
  ASSERT_TRUE(device_has_double_precision(device)) << device.name;
  DeviceCavityCentres moves(mesh, device);
  const EveningStart s = evening_start(mesh, n);
  const EveningOutcome host = evening_with_moves_on(mesh, s, nullptr);
  const EveningOutcome on_device = evening_with_moves_on(mesh, s, &moves);
  EXPECT_TRUE(host.moves.device.empty());
  EXPECT_EQ(on_device.moves.device, device.name);
  ASSERT_EQ(on_device.sweeps.size(), host.sweeps.size());
  std::size_t moved = 0;
  for (std::size_t k = 0; k < host.sweeps.size(); ++k) {
    EXPECT_EQ(on_device.sweeps[k].moved, host.sweeps[k].moved) << "sweep " << k + 1;
    moved += host.sweeps[k].moved;
  }
  ASSERT_EQ(on_device.swaps.size(), host.swaps.size());
  ASSERT_EQ(on_device.points.size(), host.points.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const SurfaceLocation &a = host.points[i], &b = on_device.points[i];
    differ += std::size_t(a.triangle != b.triangle || a.weights != b.weights || a.at.x != b.at.x ||
                          a.at.y != b.at.y || a.at.z != b.at.z);
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(moved, n);  // the evening moved particles: the centres found mattered
  std::cout << "[ info ] " << name << " n=" << n << ": " << host.sweeps.size() << " sweeps, " << moved << " moves, "
            << host.swaps.size() << " swaps tried, " << on_device.moves.launches << " launches, "
            << on_device.moves.sets_on_host << " sets on the host; proposals " << host.moves.seconds << " s on the host, "
            << on_device.moves.seconds << " s with the device (" << on_device.moves.device_seconds << " s in it)\n";
}

TEST(DeviceCavityCentres, MoveAsTheHostToTheBitOnTheCommittedMeshes) {
  const DeviceDescription device = select_device("");
  for (const char* name : {"sphere.off", "atrium.off", "torus.off"}) expect_the_hosts_moves(committed(name), name, 64, device);
  expect_the_hosts_moves(committed("torus.off"), "torus.off", 256, device);
}

// Three CGAL models: in the suite each at 64 and fandisk at 1,024 too;
// with MESHPARTICLES_DEVICE_MOVES_FULL=1 each at 64, 1,024 and 4,096 (16
// minutes on 2 cores; docs/PERFORMANCE.md).
TEST(DeviceCavityCentres, MoveAsTheHostToTheBitOnCgalModels) {
  const DeviceDescription device = select_device("");
  const bool full = std::getenv("MESHPARTICLES_DEVICE_MOVES_FULL") != nullptr;
  for (const char* name : {"bull.off", "man.off", "fandisk.off"}) {
    const std::optional<SurfaceMesh> mesh = cgal_mesh(name);
    if (!mesh) continue;
    for (const std::size_t n : {64, 1024, 4096}) {
      if (n == 64 || full || (n == 1024 && std::string(name) == "fandisk.off")) {
        expect_the_hosts_moves(*mesh, name, n, device);
      }
    }
  }
}

// Where the balls outgrow the device's largest buffer, every set is left
// to the host: the same bits, no launch.
TEST(DeviceCavityCentres, BallsTooLargeForTheDeviceLeaveTheSetsToTheHost) {
  DeviceDescription small = select_device("");
  small.max_allocation_bytes = 1024;
  const SurfaceMesh torus = committed("torus.off");
  DeviceCavityCentres moves(torus, small);
  const EveningStart s = evening_start(torus, 64);
  const EveningOutcome host = evening_with_moves_on(torus, s, nullptr);
  const EveningOutcome left = evening_with_moves_on(torus, s, &moves);
  EXPECT_EQ(left.moves.launches, 0u);
  EXPECT_GT(left.moves.sets_on_host, left.sweeps.size());
  ASSERT_EQ(left.points.size(), host.points.size());
  for (std::size_t i = 0; i < host.points.size(); ++i) {
    EXPECT_EQ(left.points[i].at.x, host.points[i].at.x);
    EXPECT_EQ(left.points[i].weights, host.points[i].weights);
  }
}

}  // namespace
}  // namespace meshparticles::testing
