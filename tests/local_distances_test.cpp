// The local store against the dense table, and the field method on it
// against the field method on the table: within the store's reach every
// distance is the table's, bit for bit; beyond it, +inf; the local field
// follows the moves exactly; and at the default cutoff the committed meshes
// make exactly the dense moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "backends/local_field_backend.hpp"
#include "backends/serial_backend.hpp"
#include "backends/serial_field_backend.hpp"
#include "geodesics/local_distances.hpp"
#include "particle_test_support.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "particles/scheme_step.hpp"
#include "pipeline/distances.hpp"
#include "quality/distribution_quality.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {

TEST(LocalDistances, WithinReachEveryDistanceIsTheTablesBitForBit) {
  const MeshWithDistances m("torus.off");
  const double radius = 0.5;
  const LocalDistances local = local_store(m.mesh, radius);
  std::size_t within = 0, beyond = 0;
  for (VertexId u = 0; u < m.mesh.vertex_count(); u += 7) {
    for (VertexId v = 0; v < m.mesh.vertex_count(); ++v) {
      const float dense = m.distances.distance(u, v);
      const float near = local.distance(u, v);
      if (std::isinf(near)) {
        // Out of reach: farther than the radius (up to the solvers' asymmetry).
        EXPECT_GT(dense, 0.98 * radius) << u << "-" << v;
        ++beyond;
      } else {
        ASSERT_EQ(near, dense) << u << "-" << v;
        EXPECT_LE(near, radius);
        ++within;
      }
    }
  }
  EXPECT_GT(within, 10000u);
  EXPECT_GT(beyond, within);
  EXPECT_EQ(local.reach(), float(radius));
}

TEST(LocalDistances, BatchedAndMarkedQueriesAgreeWithPointQueries) {
  const MeshWithDistances m("patch.off");
  const LocalDistances local = local_store(m.mesh, 0.3);
  const std::vector<VertexId> targets = {0, 5, 17, 200, 399, 5};
  std::vector<float> batched(targets.size());
  local.distances_from(17, targets, batched);
  for (std::size_t k = 0; k < targets.size(); ++k) EXPECT_EQ(batched[k], local.distance(17, targets[k]));
  std::vector<std::uint8_t> marked(m.mesh.vertex_count(), 0);
  for (const VertexId t : targets) marked[t] = 1;
  for (const VertexId first : {VertexId{0}, VertexId{17}}) {
    SCOPED_TRACE("from vertex " + std::to_string(first));
    std::vector<VertexId> seen;
    local.for_each_marked_within(17, 0.2f, marked, first, [&](VertexId v, float d) {
      seen.push_back(v);
      EXPECT_EQ(d, local.distance(17, v));
      EXPECT_LE(d, 0.2f);
    });
    for (const VertexId t : targets) {
      const bool expected = t >= first && local.distance(17, t) <= 0.2f;
      EXPECT_EQ(std::count(seen.begin(), seen.end(), t) > 0, expected) << t;
    }
  }
}

// The interleaved searches find exactly what one search at a time finds:
// for every vertex, in balls of every size (empty, one vertex, the mesh's),
// in more balls than one group searches at once and in a partial group.
TEST(LocalDistances, InterleavedSearchesFindWhatOneSearchFinds) {
  const MeshWithDistances m("patch.off");
  const LocalDistances local = local_store(m.mesh, 0.3);
  std::vector<std::shared_ptr<const Ball>> held;
  for (VertexId u = 0; u < m.mesh.vertex_count(); u += 11) held.push_back(local.ball(u));
  const Ball empty, single{{42}, {0.25f}};
  std::vector<const Ball*> balls = {&empty, &single};
  for (const auto& ball : held) balls.push_back(ball.get());
  ASSERT_GT(balls.size(), 32u);
  std::vector<float> found(balls.size());
  std::size_t inside = 0;
  for (VertexId v = 0; v < m.mesh.vertex_count(); ++v) {
    distances_to(v, balls, found);
    for (std::size_t k = 0; k < balls.size(); ++k) {
      const auto one = distance_in_ball(*balls[k], v);
      ASSERT_EQ(found[k], one ? *one : INFINITY) << "vertex " << v << " in ball " << k;
      inside += one.has_value();
    }
  }
  EXPECT_GT(inside, 1000u);
  std::vector<std::size_t> visited;
  for_each_distance_to(
      17, balls.size(), [&](std::size_t k) { return k % 3 ? balls[k] : nullptr; },
      [&](std::size_t k, float d) {
        visited.push_back(k);
        const auto one = distance_in_ball(*balls[k], 17);
        EXPECT_EQ(d, one ? *one : INFINITY) << k;
      });
  std::vector<std::size_t> expected;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    if (k % 3) expected.push_back(k);
  }
  EXPECT_EQ(visited, expected);
}

// A budget smaller than the balls in use evicts the least recently used;
// answers stay the same.
TEST(LocalDistances, ASmallCacheEvictsAndRecomputesTheSameBalls) {
  const MeshWithDistances m("torus.off");
  const LocalDistances roomy = local_store(m.mesh, 0.5);
  const LocalDistances tight = local_store(m.mesh, 0.5, 16 * 1024);  // about 25 balls
  for (int round = 0; round < 2; ++round) {
    for (VertexId u = 0; u < m.mesh.vertex_count(); u += 50) {
      for (const VertexId v : {VertexId(3), VertexId(700), VertexId(u + 1)}) {
        ASSERT_EQ(tight.distance(u, v), roomy.distance(u, v));
      }
    }
  }
  EXPECT_GT(tight.statistics().balls_evicted, 0u);
  EXPECT_LE(tight.statistics().peak_bytes, 16 * 1024 + 4 * 1024);
  EXPECT_EQ(roomy.statistics().balls_evicted, 0u);
}

// Balls requested for the helper threads are the balls solved on demand,
// each solved once, whichever thread gets to it first: the reads below run
// against the helpers, from the other end of the queue.
TEST(LocalDistances, RequestedBallsAreSolvedOnceAndAreTheBallsSolvedOnDemand) {
  const MeshWithDistances m("torus.off");
  const double radius = 0.5;
  const LocalDistances on_demand = local_store(m.mesh, radius, std::uint64_t{1} << 30, 1);
  const LocalDistances helped = local_store(m.mesh, radius, std::uint64_t{1} << 30, 4);
  std::vector<VertexId> wanted;
  for (VertexId v = 0; v < m.mesh.vertex_count(); v += 2) wanted.push_back(v);
  helped.request(wanted);
  helped.request(wanted);  // asked twice: still solved once
  for (auto v = wanted.rbegin(); v != wanted.rend(); ++v) {
    const auto got = helped.ball(*v);
    const auto expected = on_demand.ball(*v);
    ASSERT_EQ(got->vertices, expected->vertices) << "vertex " << *v;
    ASSERT_EQ(got->distances, expected->distances) << "vertex " << *v;
  }
  EXPECT_EQ(helped.statistics().balls_computed, wanted.size());
  EXPECT_EQ(on_demand.statistics().background_seconds, 0.0);  // one thread: no helper
}

// A prefetch on threads returns when its balls are done, not at the
// caller's next look 0.1 s on (it slept that long between looks: most of
// the measurement of a run of a few hundred particles). Balls of one
// vertex each, a few milliseconds in all (7 to 10 ms on 2 cores): the
// quickest of three prefetches returns before the old sleep would have
// ended. No speed is asserted, only that the caller was not made to wait it.
TEST(LocalDistances, APrefetchOnThreadsReturnsWhenItsBallsAreDone) {
  const SurfaceMesh mesh = committed("atrium.off");
  std::vector<VertexId> all(mesh.vertex_count());
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) all[v] = v;
  double quickest = 1e9;
  for (int trial = 0; trial < 3; ++trial) {
    const LocalDistances store = local_store(mesh, 1e-9, std::uint64_t{1} << 30, 2);
    store.prefetch(all);
    EXPECT_EQ(store.statistics().balls_computed, all.size());
    quickest = std::min(quickest, store.statistics().seconds);
  }
  EXPECT_LT(quickest, 0.1) << "seconds, the quickest of three prefetches of " << all.size() << " balls";
}

// Whether new candidates' balls come from helpers or are solved when read,
// a run makes the same moves and energies.
TEST(LocalField, HelperThreadsChangeNothing) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 300;
  const EnergyParams energy = m.default_energy(particles);
  const double radius = cutoff_radius(m.mesh, particles);
  const auto start = place_particles(m.mesh, {Init::random, particles, 5, std::nullopt});
  std::vector<RunOutcome> outcomes;
  for (const unsigned threads : {1u, 4u}) {
    const LocalDistances local = local_store(m.mesh, radius, std::uint64_t{1} << 30, threads);
    LocalFieldBackend field(m.mesh, local, energy, WeightFormat::float32, 0);
    outcomes.push_back(run_particles(field, start, {Scheme::sequential, 1, 100, true}));
  }
  EXPECT_GT(outcomes[0].trace.front().moved, 100u);
  EXPECT_EQ(outcomes[1].positions, outcomes[0].positions);
  ASSERT_EQ(outcomes[1].trace.size(), outcomes[0].trace.size());
  for (std::size_t i = 0; i < outcomes[0].trace.size(); ++i) {
    EXPECT_EQ(outcomes[1].trace[i].energy, outcomes[0].trace[i].energy) << "iteration " << i;
  }
}

// Each iteration's record counts the balls solved while it ran: on one
// thread (the caller solves every ball, when a decision first reads it)
// those and the start's add up to all the store solved, and the time they
// took is the particle loop's.
TEST(LocalField, EachIterationRecordsTheBallsItSolved) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 300;
  const EnergyParams energy = m.default_energy(particles);
  const double radius = cutoff_radius(m.mesh, particles);
  const auto start = place_particles(m.mesh, {Init::random, particles, 5, std::nullopt});
  const LocalDistances for_start = local_store(m.mesh, radius, std::uint64_t{1} << 30, 1);
  LocalFieldBackend(m.mesh, for_start, energy, WeightFormat::float32, 0).set_positions(start);
  const std::size_t start_balls = for_start.statistics().balls_computed;

  const LocalDistances local = local_store(m.mesh, radius, std::uint64_t{1} << 30, 1);
  LocalFieldBackend field(m.mesh, local, energy, WeightFormat::float32, 0);
  const RunOutcome outcome = run_particles(field, start, {Scheme::sequential, 1, 100, true}, &local);
  std::size_t iteration_balls = 0;
  for (const IterationRecord& record : outcome.trace) {
    ASSERT_TRUE(record.balls_solved && record.ball_ms);
    iteration_balls += *record.balls_solved;
    EXPECT_EQ(*record.balls_solved > 0, *record.ball_ms > 0) << *record.balls_solved << " balls";
  }
  EXPECT_GT(iteration_balls, 0u) << "moves bring new candidates";
  EXPECT_EQ(start_balls + iteration_balls, local.statistics().balls_computed);

  LocalFieldBackend unrecorded(m.mesh, local, energy, WeightFormat::float32, 0);
  EXPECT_FALSE(run_particles(unrecorded, start, {Scheme::sequential, 1, 1, true}).trace.front().balls_solved);
}

// The local field follows the moves exactly: after many iterations it holds
// what a rebuild gives, at every candidate.
TEST(LocalField, IncrementalUpdatesMatchARebuild) {
  const MeshWithDistances m("torus.off");
  const std::size_t particles = 200;
  const EnergyParams energy = m.default_energy(particles);
  const LocalDistances local = local_store(m.mesh, cutoff_radius(m.mesh, particles));
  LocalFieldBackend field(m.mesh, local, energy, WeightFormat::float32, 0);
  const auto start = place_particles(m.mesh, {Init::random, particles, 3, std::nullopt});
  const RunOutcome outcome = run_particles(field, start, {Scheme::colored, 2, 200, true});
  ASSERT_EQ(outcome.trace.size(), 200u) << "colored K=2 keeps moving here";
  std::vector<std::int64_t> incremental;
  const std::vector<VertexId> candidates = field.candidates();
  for (const VertexId v : candidates) incremental.push_back(field.field(v));
  field.rebuild_field();
  ASSERT_EQ(field.candidates(), candidates);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    ASSERT_EQ(field.field(candidates[k]), incremental[k]) << "vertex " << candidates[k];
  }
}

// The same moves as the field method on the table, step for step, on every
// committed mesh at its benchmark n, at the default cutoff.
class LocalAgreesWithDense : public ::testing::TestWithParam<std::pair<const char*, std::size_t>> {};

TEST_P(LocalAgreesWithDense, SameMovesAtTheDefaultCutoff) {
  const auto [name, particles] = GetParam();
  const MeshWithDistances m(name);
  const EnergyParams energy = m.default_energy(particles);
  const LocalDistances local = local_store(m.mesh, cutoff_radius(m.mesh, particles));
  const auto start = place_particles(m.mesh, {Init::farthest, particles, 1, std::nullopt});
  for (const Scheme scheme : {Scheme::sequential, Scheme::monotone}) {
    SCOPED_TRACE(scheme_name(scheme));
    SerialFieldBackend dense(m.mesh, m.distances, energy, WeightFormat::float32, 0);
    LocalFieldBackend near(m.mesh, local, energy, WeightFormat::float32, 0);
    const RunOutcome expected = run_particles(dense, start, {scheme, kDefaultColors, 500, true});
    const RunOutcome got = run_particles(near, start, {scheme, kDefaultColors, 500, true});
    EXPECT_TRUE(got.converged);
    EXPECT_EQ(got.positions, expected.positions);
    ASSERT_EQ(got.trace.size(), expected.trace.size());
    for (std::size_t i = 0; i < got.trace.size(); ++i) {
      EXPECT_EQ(got.trace[i].moved, expected.trace[i].moved) << "iteration " << i;
      // The local energy leaves out the pairs beyond the cutoff (w < 1e-6 each).
      EXPECT_NEAR(got.trace[i].energy, expected.trace[i].energy, 2e-5 * expected.trace[i].energy);
      EXPECT_LE(got.trace[i].energy, expected.trace[i].energy);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CommittedMeshes, LocalAgreesWithDense,
                         ::testing::Values(std::pair{"torus.off", std::size_t{512}},
                                           std::pair{"sphere.off", std::size_t{1024}},
                                           std::pair{"patch.off", std::size_t{100}},
                                           std::pair{"atrium.off", std::size_t{1024}}),
                         [](const auto& param_info) { return mesh_stem(param_info.param.first); });

// The serial reference reads the same truncated distances through the store
// interface: on local balls it makes the local field's choices.
TEST(LocalField, TheReferenceOnLocalBallsMakesTheSameRun) {
  const MeshWithDistances m("patch.off");
  const std::size_t particles = 60;
  const EnergyParams energy = m.default_energy(particles);
  const LocalDistances local = local_store(m.mesh, cutoff_radius(m.mesh, particles, 3.0));
  const auto start = place_particles(m.mesh, {Init::farthest, particles, 2, std::nullopt});
  SerialBackend reference(m.mesh, local, energy);
  LocalFieldBackend field(m.mesh, local, energy, WeightFormat::float32, 0);
  const RunOutcome expected = run_particles(reference, start, {Scheme::sequential, 1, 100, true});
  const RunOutcome got = run_particles(field, start, {Scheme::sequential, 1, 100, true});
  EXPECT_EQ(got.positions, expected.positions);
  EXPECT_NEAR(got.trace.back().energy, expected.trace.back().energy, 1e-5 * expected.trace.back().energy);
}

// The quality of `positions` on the patch through balls of `radius` and
// through the table.
std::pair<DistributionQuality, DistributionQuality> quality_on_balls_and_table(
    const MeshWithDistances& m, std::span<const VertexId> positions, const EnergyParams& energy, double radius) {
  const LocalDistances local = local_store(m.mesh, radius);
  const auto to_nearest = distance_to_nearest_particle(m.mesh, GeodesicMethod::fast_marching, positions);
  return {measure_quality(m.mesh, local, positions, energy, to_nearest, true),
          measure_quality(m.mesh, m.distances, positions, energy, to_nearest, true)};
}

// Quality through a local store: the pairs within reach, and a particle
// with no neighbour within reach (its component holds others) measured by a
// ball of its own, whose pairs join the energy: the table's figures.
TEST(LocalField, QualityFindsTheNeighbourOfAParticleAloneWithinTheCutoff) {
  const MeshWithDistances m("patch.off");
  const std::vector<VertexId> positions = {0, 1, 399};  // two neighbours in a corner, one far away
  const EnergyParams energy{Potential::exp, 1.0};  // the far pair still weighs exp(-0.7)
  const auto [near, dense] = quality_on_balls_and_table(m, positions, energy, 0.2);
  EXPECT_EQ(near.alone, 0u);
  EXPECT_EQ(dense.alone, 0u);
  EXPECT_EQ(near.nn_min, dense.nn_min);
  ASSERT_TRUE(near.nn_mean && dense.nn_mean);
  EXPECT_NEAR(*near.nn_mean, *dense.nn_mean, 1e-4 * *dense.nn_mean);
  EXPECT_NEAR(near.energy, dense.energy, 1e-4 * dense.energy);
  EXPECT_EQ(near.cover, dense.cover);
}

// With balls that reach every vertex, the local store sees every pair the
// table does, each once: the same nearest neighbours, energy and stacks,
// particles on one vertex and on vertices in either order included.
TEST(LocalField, QualityWithBallsThatReachEverywhereIsTheTables) {
  const MeshWithDistances m("patch.off");
  std::vector<VertexId> positions = place_particles(m.mesh, {Init::random, 60, 4, std::nullopt});
  positions[7] = positions[3];  // a stack, the later index on it
  const auto [from_balls, from_table] = quality_on_balls_and_table(m, positions, {Potential::exp, 0.3}, 10.0);
  EXPECT_EQ(from_balls.alone, 0u);
  EXPECT_EQ(from_balls.stacked, 1u);
  EXPECT_EQ(from_balls.nn_min, from_table.nn_min);
  ASSERT_TRUE(from_balls.nn_mean && from_table.nn_mean);
  EXPECT_NEAR(*from_balls.nn_mean, *from_table.nn_mean, 1e-12 * *from_table.nn_mean);
  EXPECT_NEAR(*from_balls.nn_std, *from_table.nn_std, 1e-9 * *from_table.nn_std);
  EXPECT_NEAR(from_balls.energy, from_table.energy, 1e-12 * from_table.energy);
}

}  // namespace
}  // namespace meshparticles::testing
