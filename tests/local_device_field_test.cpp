// The field backend on the device over local balls against its serial twin
// (LocalFieldBackend) and against itself: the same moves step for step on
// the committed meshes, F at the candidates exact after many moves (a
// rebuild gives the same bits) and within the last bits of the twin's
// (the device's exp and the host's may differ there), through repacks of
// the pool of rows.
#include <gtest/gtest.h>

#include <cmath>

#include "backends/backend_factory.hpp"
#include "backends/field_backend.hpp"
#include "backends/local_device_field_backend.hpp"
#include "backends/local_field_backend.hpp"
#include "fixtures/mesh_generator.hpp"
#include "particle_test_support.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "pipeline/distances.hpp"

namespace meshparticles::testing {
namespace {

std::unique_ptr<LocalDeviceFieldBackend> device_twin(const SurfaceMesh& mesh, const LocalDistances& balls,
                                                     const EnergyParams& energy, std::size_t work_group = 32,
                                                     double pool_headroom = 1.0,
                                                     std::size_t upload_piece = std::size_t{1} << 22) {
  UpdateKernel kernel = default_update_kernel(field_backend(), mesh.max_valence() + 1, 64);
  kernel.work_group_size = work_group;
  return std::make_unique<LocalDeviceFieldBackend>(select_device(""), kernel, BackendInputs{mesh, balls, energy},
                                                   balls, pool_headroom, upload_piece);
}

// 200 particles on the torus at the default σ, its balls, and a start.
struct TorusRun {
  explicit TorusRun(Init init)
      : energy(m.default_energy(particles)),
        balls(local_store(m.mesh, cutoff_radius(m.mesh, particles))),
        start(place_particles(m.mesh, {init, particles, 3, std::nullopt})) {}
  const MeshWithDistances m{"torus.off"};
  const std::size_t particles = 200;
  const EnergyParams energy;
  const LocalDistances balls;
  const std::vector<VertexId> start;
};

class LocalDeviceField : public ::testing::TestWithParam<std::pair<const char*, std::size_t>> {};

TEST_P(LocalDeviceField, MakesTheSerialTwinsMoves) {
  const auto [name, particles] = GetParam();
  const MeshWithDistances m(name);
  const EnergyParams energy = m.default_energy(particles);
  const LocalDistances balls = local_store(m.mesh, cutoff_radius(m.mesh, particles));
  for (const Init init : {Init::farthest, Init::random}) {
    const auto start = place_particles(m.mesh, {init, particles, 5, std::nullopt});
    for (const Scheme scheme : {Scheme::sequential, Scheme::monotone, Scheme::colored, Scheme::synchronous}) {
      SCOPED_TRACE(init_name(init) + " " + scheme_name(scheme));
      LocalFieldBackend twin(m.mesh, balls, energy, WeightFormat::float32, 0);
      const auto device = device_twin(m.mesh, balls, energy);
      // colored and synchronous may keep moving: a few iterations are enough.
      const bool may_oscillate = scheme == Scheme::colored || scheme == Scheme::synchronous;
      const RunSettings settings{scheme, kDefaultColors, std::size_t{may_oscillate ? 30u : 500u}, true};
      const RunOutcome expected = run_particles(twin, start, settings);
      const RunOutcome got = run_particles(*device, start, settings);
      EXPECT_EQ(got.positions, expected.positions);
      ASSERT_EQ(got.trace.size(), expected.trace.size());
      for (std::size_t i = 0; i < got.trace.size(); ++i) {
        EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved) << "iteration " << i;
        EXPECT_NEAR(got.trace[i].energy, expected.trace[i].energy, 1e-6 * expected.trace[i].energy);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CommittedMeshes, LocalDeviceField,
                         ::testing::Values(std::pair{"torus.off", std::size_t{512}},
                                           std::pair{"sphere.off", std::size_t{1024}},
                                           std::pair{"patch.off", std::size_t{100}}),
                         [](const auto& param_info) { return mesh_stem(param_info.param.first); });

// Colored K = 2 keeps the torus's particles moving: thousands of moves, the
// candidates change all the time, and with 2% headroom the pool fills and
// is repacked again and again, its rows sent in pieces of about 1,000
// entries (a few balls each). F at
// every candidate is then what a rebuild gives, bit for bit, and within the
// last bits of the serial twin's after the same moves.
TEST(LocalDeviceField, IncrementalUpdatesMatchARebuildThroughRepacks) {
  const TorusRun torus(Init::random);
  const auto& [m, particles, energy, balls, start] = torus;
  LocalFieldBackend twin(m.mesh, balls, energy, WeightFormat::float32, 0);
  const RunOutcome twin_outcome = run_particles(twin, start, {Scheme::colored, 2, 100, true});
  for (const std::size_t work_group : {std::size_t{1}, std::size_t{7}, std::size_t{64}}) {
    SCOPED_TRACE("wg " + std::to_string(work_group));
    const auto device = device_twin(m.mesh, balls, energy, work_group, 0.02, 1000);
    const RunOutcome outcome = run_particles(*device, start, {Scheme::colored, 2, 100, true});
    ASSERT_EQ(outcome.trace.size(), 100u) << "the run settled: the test needs moves";
    ASSERT_EQ(outcome.positions, twin_outcome.positions);
    EXPECT_GT(device->repacks(), 1u) << "the test needs the pool repacked";
    const std::vector<VertexId> candidates = device->candidates();
    ASSERT_EQ(candidates, twin.candidates());
    const std::vector<std::int64_t> incremental = device->candidate_field();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const double twin_value = double(twin.field(candidates[k]));
      ASSERT_NEAR(double(incremental[k]), twin_value, 1e-6 * twin_value) << "vertex " << candidates[k];
    }
    device->rebuild_field();
    EXPECT_EQ(device->candidate_field(), incremental);
  }
}

// The monotone scheme undoes an attempt that raised the energy by setting
// the positions back. The particles that differ go back as moves, as a
// colour's commit does, not through a rebuild; F at the candidates is then
// what a rebuild from those positions gives, bit for bit.
TEST(LocalDeviceField, PositionsSetBackAreMovedNotRebuilt) {
  const TorusRun torus(Init::farthest);
  const auto& [m, particles, energy, balls, start] = torus;
  const auto device = device_twin(m.mesh, balls, energy);
  device->set_positions(start);
  for (int i = 0; i < 2; ++i) device->iterate(Scheme::colored, 2);
  std::size_t differing = 0;
  const std::vector<VertexId> moved = device->positions();
  for (std::size_t i = 0; i < particles; ++i) differing += moved[i] != start[i];
  ASSERT_GT(differing, 0u) << "the test needs moves to undo";
  ASSERT_LE(2 * differing, particles) << "the test needs few enough moves to undo them as moves";

  const std::size_t rebuilds = device->rebuilds();
  device->set_positions(start);
  EXPECT_EQ(device->rebuilds(), rebuilds) << "set back by a rebuild";
  EXPECT_EQ(device->positions(), start);
  const auto fresh = device_twin(m.mesh, balls, energy);
  fresh->set_positions(start);
  EXPECT_EQ(device->candidates(), fresh->candidates());
  EXPECT_EQ(device->candidate_field(), fresh->candidate_field());
  EXPECT_EQ(device->total_energy(), fresh->total_energy());
  EXPECT_EQ(device->iterate(Scheme::colored, 2).moved, fresh->iterate(Scheme::colored, 2).moved);
  EXPECT_EQ(device->positions(), fresh->positions());
}

// A mesh whose table the device could not hold is refused on the dense
// table and accepted on local distances, before anything is computed.
TEST(LocalDeviceField, AMeshPastTheDevicesTableIsPlannedOnLocalDistances) {
  const DeviceDescription device = select_device("");
  const auto vertices = std::size_t(1.2 * std::sqrt(double(device.max_allocation_bytes) / sizeof(float)));
  const SurfaceMesh mesh = generate_mesh_at("sphere", vertices);
  BackendRequest request;
  request.name = "field";
  EXPECT_THROW(check_backend(request, mesh, 1000, /*dense_distances=*/true), UserError);
  EXPECT_NO_THROW(check_backend(request, mesh, 1000, /*dense_distances=*/false));
}

}  // namespace
}  // namespace meshparticles::testing
