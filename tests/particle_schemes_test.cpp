// Whole runs: the schemes' promises (sequential never raises the energy and
// stops; every scheme separates the paper's stacked start) and the backends'
// agreement over 50 iterations.
#include <gtest/gtest.h>

#include <set>

#include "backends/serial_field_backend.hpp"
#include "particle_test_support.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "particles/scheme_step.hpp"

namespace meshparticles::testing {
namespace {


// The torus with 200 farthest-point particles has no near-ties along these
// runs (a float near-tie would show up as a different vertex below).
TEST(WholeRuns, SynchronousAndColoredAgreeOnEveryBackend) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::farthest, particles, 1, std::nullopt});
  for (const auto& [scheme, colors] : {std::pair{Scheme::synchronous, 1u}, std::pair{Scheme::colored, 8u}}) {
    SCOPED_TRACE(scheme_name(scheme));
    SerialBackend reference(m.mesh, m.distances, energy);
    const RunOutcome expected = run(reference, start, scheme, colors, 50);
    ASSERT_EQ(expected.trace.size(), 50u) << "the runs should still be moving particles";
    for (const KernelSize& size : {KernelSize{"naive", 16, 0}, KernelSize{"naive", 5, 0},
                                   KernelSize{"tiled", 64, 256}, KernelSize{"tiled", 24, 7},
                                   KernelSize{"field", 64, 0}, KernelSize{"field", 5, 0}}) {
      SCOPED_TRACE(describe(size));
      auto kernel = device_backend(m, energy, size.kind, size.work_group, size.tile);
      const RunOutcome got = run(*kernel, start, scheme, colors, 50);
      EXPECT_EQ(got.positions, expected.positions);
      ASSERT_EQ(got.trace.size(), expected.trace.size());
      for (std::size_t i = 0; i < got.trace.size(); ++i) {
        EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved) << "iteration " << i;
        EXPECT_NEAR(got.trace[i].energy, expected.trace[i].energy, 1e-5 * expected.trace[i].energy);
        ASSERT_TRUE(got.trace[i].kernel_ms.has_value());
      }
    }
    SerialFieldBackend twin(m.mesh, m.distances, energy, WeightFormat::float32, 0);
    const RunOutcome got = run(twin, start, scheme, colors, 50);
    EXPECT_EQ(got.positions, expected.positions) << "serial-field";
    for (std::size_t i = 0; i < got.trace.size(); ++i) {
      EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved) << "serial-field, iteration " << i;
      EXPECT_NEAR(got.trace[i].energy, expected.trace[i].energy, 1e-5 * expected.trace[i].energy);
    }
  }
}

// The same whole-run agreement under the Gaussian potential (colored, one
// size per kernel and the twin).
TEST(WholeRuns, GaussianPotentialAgreesOnEveryBackend) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles, Potential::gauss);
  const auto start = place_particles(m.mesh, {Init::farthest, particles, 1, std::nullopt});
  SerialBackend reference(m.mesh, m.distances, energy);
  const RunOutcome expected = run(reference, start, Scheme::colored, 8, 30);
  ASSERT_GT(expected.trace.front().moved, 0u);
  std::vector<std::unique_ptr<ParticleBackend>> backends;
  backends.push_back(std::make_unique<SerialFieldBackend>(m.mesh, m.distances, energy, WeightFormat::float32, 0));
  backends.push_back(device_backend(m, energy, "naive", 16));
  backends.push_back(device_backend(m, energy, "tiled", 32, 64));
  backends.push_back(device_backend(m, energy, "field", 32));
  for (const auto& backend : backends) {
    const RunOutcome got = run(*backend, start, Scheme::colored, 8, 30);
    EXPECT_EQ(got.positions, expected.positions);
    ASSERT_EQ(got.trace.size(), expected.trace.size());
    for (std::size_t i = 0; i < got.trace.size(); ++i) {
      EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved) << "iteration " << i;
      EXPECT_NEAR(got.trace[i].energy, expected.trace[i].energy, 1e-5 * expected.trace[i].energy);
    }
  }
}

// Every backend runs the paper's sequential loop (on a device: one sub-step
// per particle, each taking its best candidate), from a spread start and from
// the stacked one.
TEST(WholeRuns, SequentialAgreesOnEveryBackend) {
  const MeshWithDistances m("patch.off");
  const std::size_t particles = 60;
  const EnergyParams energy = m.default_energy(particles);
  for (const Init init : {Init::farthest, Init::v0}) {
    SCOPED_TRACE(init_name(init));
    const auto start = place_particles(m.mesh, {init, particles, 2, std::nullopt});
    SerialBackend reference(m.mesh, m.distances, energy);
    const RunOutcome expected = run(reference, start, Scheme::sequential, 1, 30);
    ASSERT_GT(expected.trace.size(), 2u);
    std::vector<std::unique_ptr<ParticleBackend>> backends;
    backends.push_back(std::make_unique<SerialFieldBackend>(m.mesh, m.distances, energy, WeightFormat::float32, 0));
    backends.push_back(device_backend(m, energy, "naive", 8));
    backends.push_back(device_backend(m, energy, "tiled", 16, 32));
    backends.push_back(device_backend(m, energy, "field", 16));
    for (const auto& backend : backends) {
      const RunOutcome got = run(*backend, start, Scheme::sequential, 1, 30);
      EXPECT_EQ(got.positions, expected.positions);
      ASSERT_EQ(got.trace.size(), expected.trace.size());
      for (std::size_t i = 0; i < got.trace.size(); ++i) EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved);
    }
  }
}

TEST(Sequential, EnergyNeverIncreasesAndTheRunStops) {
  for (const char* name : {"torus.off", "patch.off"}) {
    SCOPED_TRACE(name);
    const MeshWithDistances m(name);
    for (const Init init : {Init::farthest, Init::v0}) {
      const std::size_t particles = 100;
      SerialBackend serial(m.mesh, m.distances, m.default_energy(particles));
      const auto start = place_particles(m.mesh, {init, particles, 3, std::nullopt});
      const RunOutcome outcome = run(serial, start, Scheme::sequential, 1, 2000);
      EXPECT_TRUE(outcome.converged) << init_name(init);
      double previous = outcome.initial_energy;
      for (const auto& record : outcome.trace) {
        EXPECT_LE(record.energy, previous * (1 + 1e-12));
        previous = record.energy;
      }
      EXPECT_LT(outcome.trace.back().energy, outcome.initial_energy);
    }
  }
}

// The monotone scheme's promise, on every backend: each iteration that moves
// particles lowers the energy the backend reports, so the run stops with no
// particle moving - here from a configuration where colored never settles
// (torus, n = 200, K = 2: particles of one colour keep swapping back and
// forth; Field tests rely on it running 1,000 iterations).
TEST(Monotone, SettlesWhereColoredOscillatesAndNeverRaisesTheEnergy) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::random, particles, 3, std::nullopt});
  SerialFieldBackend colored(m.mesh, m.distances, energy, WeightFormat::float32, 0);
  ASSERT_FALSE(run(colored, start, Scheme::colored, 2, 300).converged) << "the test needs a case colored cannot settle";

  std::vector<std::unique_ptr<ParticleBackend>> backends;
  backends.push_back(std::make_unique<SerialBackend>(m.mesh, m.distances, energy));
  backends.push_back(std::make_unique<SerialFieldBackend>(m.mesh, m.distances, energy, WeightFormat::float32, 0));
  backends.push_back(device_backend(m, energy, "naive", 16));
  backends.push_back(device_backend(m, energy, "tiled", 32, 64));
  backends.push_back(device_backend(m, energy, "field", 32));
  std::vector<RunOutcome> outcomes;
  for (const auto& backend : backends) {
    SCOPED_TRACE(backend->device_name());
    const RunOutcome outcome = run(*backend, start, Scheme::monotone, 2, 300);
    EXPECT_TRUE(outcome.converged);
    double previous = outcome.initial_energy;
    std::size_t redone = 0;
    for (const auto& record : outcome.trace) {
      if (record.moved > 0) {
        EXPECT_LT(record.energy, previous);
      } else {
        EXPECT_EQ(record.energy, previous);
      }
      previous = record.energy;
      redone += !record.redone_as.empty();
    }
    EXPECT_GT(redone, 0u) << "some iteration should have needed more colours";
    outcomes.push_back(outcome);
  }
  // The field device and its serial twin count the same units: the same run.
  const RunOutcome& twin = outcomes[1];
  const RunOutcome& field = outcomes[4];
  EXPECT_EQ(field.positions, twin.positions);
  ASSERT_EQ(field.trace.size(), twin.trace.size());
  for (std::size_t i = 0; i < field.trace.size(); ++i) {
    EXPECT_EQ(field.trace[i].moved, twin.trace[i].moved) << "iteration " << i;
    EXPECT_EQ(field.trace[i].redone_as, twin.trace[i].redone_as) << "iteration " << i;
  }
}

// An undone attempt leaves no trace: a redone iteration's result is what the
// kept attempt gives from the iteration's own start.
TEST(Monotone, ARedoneIterationStartsAgainFromItsStart) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  SerialFieldBackend monotone(m.mesh, m.distances, energy, WeightFormat::float32, 0);
  SerialFieldBackend replay(m.mesh, m.distances, energy, WeightFormat::float32, 0);
  monotone.set_positions(place_particles(m.mesh, {Init::random, particles, 3, std::nullopt}));
  double current = monotone.total_energy();
  std::size_t replayed = 0;
  for (std::size_t iteration = 0; iteration < 300; ++iteration) {
    const std::vector<VertexId> before = monotone.positions();
    const IterationStats stats = iterate_scheme(monotone, Scheme::monotone, 2, current);
    if (stats.attempts > 1 && stats.kept.rfind("colored K=", 0) == 0) {
      replay.set_positions(before);
      const IterationStats again = replay.iterate(Scheme::colored, unsigned(std::stoul(stats.kept.substr(10))));
      EXPECT_EQ(monotone.positions(), replay.positions()) << "iteration " << iteration << ", " << stats.kept;
      EXPECT_EQ(stats.moved, again.moved);
      EXPECT_EQ(stats.energy, again.energy);
      ++replayed;
    }
    EXPECT_EQ(stats.energy, monotone.total_energy()) << "the reported energy is the positions'";
    current = stats.energy;
    if (stats.moved == 0) break;
  }
  EXPECT_GT(replayed, 0u);
}

// From the paper's stacked start too, and with the default colours.
TEST(Monotone, DrainsThePapersStackWithoutRaisingTheEnergy) {
  const MeshWithDistances m("patch.off");
  const std::size_t particles = 100;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::v0, particles, 0, VertexId{0}});
  for (const auto& backend : std::vector<std::shared_ptr<ParticleBackend>>{
           std::make_shared<SerialBackend>(m.mesh, m.distances, energy), device_backend(m, energy, "field", 32)}) {
    SCOPED_TRACE(backend->device_name());
    const RunOutcome outcome = run(*backend, start, Scheme::monotone, kDefaultColors, 1000);
    EXPECT_TRUE(outcome.converged);
    EXPECT_EQ(std::set<VertexId>(outcome.positions.begin(), outcome.positions.end()).size(), particles);
    double previous = outcome.initial_energy;
    for (const auto& record : outcome.trace) {
      EXPECT_LE(record.energy, previous);
      previous = record.energy;
    }
  }
}

// Colour groups of one particle each see every move before them: that is
// the sequential loop. One group is the synchronous step.
TEST(Schemes, ColoredGeneralizesTheOtherTwo) {
  const MeshWithDistances m("patch.off");
  const std::size_t particles = 60;
  const auto start = place_particles(m.mesh, {Init::random, particles, 5, std::nullopt});
  const EnergyParams energy = m.default_energy(particles);
  SerialBackend a(m.mesh, m.distances, energy), b(m.mesh, m.distances, energy);
  EXPECT_EQ(run(a, start, Scheme::sequential, 1, 20).positions,
            run(b, start, Scheme::colored, unsigned(particles), 20).positions);
  EXPECT_EQ(run(a, start, Scheme::synchronous, 1, 20).positions, run(b, start, Scheme::colored, 1, 20).positions);
}

// The paper's start stacks every particle on one vertex; the stack rank rule
// must spread them over distinct vertices in every scheme (n <= V/2).
TEST(Schemes, EverySchemeSeparatesThePapersStart) {
  const MeshWithDistances m("patch.off");
  const std::size_t particles = m.mesh.vertex_count() / 2;
  const EnergyParams energy = m.default_energy(particles);
  const auto start = place_particles(m.mesh, {Init::v0, particles, 0, VertexId{0}});
  auto distinct = [](const std::vector<VertexId>& positions) {
    return std::set<VertexId>(positions.begin(), positions.end()).size();
  };
  SerialBackend serial(m.mesh, m.distances, energy);
  auto tiled = device_backend(m, energy, "tiled", 64, 128);
  EXPECT_EQ(distinct(run(serial, start, Scheme::sequential, 1, 300).positions), particles);
  for (const auto& [scheme, colors] : {std::pair{Scheme::synchronous, 1u}, std::pair{Scheme::colored, 8u}}) {
    SCOPED_TRACE(scheme_name(scheme));
    EXPECT_EQ(distinct(run(serial, start, scheme, colors, 300).positions), particles);
    EXPECT_EQ(distinct(run(*tiled, start, scheme, colors, 300).positions), particles);
  }
}

}  // namespace
}  // namespace meshparticles::testing
