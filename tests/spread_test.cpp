// The default method, spread: the Voronoi diagram it keeps agrees with
// solves from every particle, the refined working mesh is the input
// surface, and farthest-point optimization spreads particles more evenly
// than the farthest start it begins from without giving up its cover.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "common/random.hpp"
#include "geodesics/local_distances.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "mesh/midpoint_refinement.hpp"
#include "particles/particle_file.hpp"
#include "particles/farthest_point_optimization.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_voronoi.hpp"
#include "particle_test_support.hpp"
#include "pipeline/run_pipeline.hpp"
#include "pipeline/spread_method.hpp"
#include "quality/distribution_quality.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {


// The distance from every vertex to the nearest of `particles`, each
// particle's own full solve: what the diagram's distances approximate.
std::vector<double> nearest_by_full_solves(const SurfaceMesh& mesh, const std::vector<VertexId>& particles) {
  const auto solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  std::vector<double> nearest(mesh.vertex_count(), std::numeric_limits<double>::infinity()), from(mesh.vertex_count());
  for (const VertexId p : particles) {
    solver->solve(p, from, scratch);
    for (std::size_t v = 0; v < from.size(); ++v) nearest[v] = std::min(nearest[v], from[v]);
  }
  return nearest;
}

TEST(ParticleVoronoi, AgreesWithFullSolvesAfterParticlesComeAndGo) {
  const SurfaceMesh mesh = committed("sphere.off");
  const auto solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  constexpr std::uint32_t kParticles = 80;
  ParticleVoronoi voronoi(mesh, *solver, kParticles);
  SplitMix64 random(7);
  std::vector<VertexId> at(kParticles);
  std::set<VertexId> taken;
  const auto free_vertex = [&] {
    VertexId v;
    do v = VertexId(random.below(mesh.vertex_count()));
    while (taken.count(v));
    return v;
  };
  for (std::uint32_t p = 0; p < kParticles; ++p) {
    at[p] = free_vertex();
    taken.insert(at[p]);
    voronoi.insert(p, at[p]);
  }
  for (int step = 0; step < 300; ++step) {  // remove one, put it back elsewhere
    const auto p = std::uint32_t(random.below(kParticles));
    voronoi.remove(p);
    taken.erase(at[p]);
    at[p] = free_vertex();
    taken.insert(at[p]);
    voronoi.insert(p, at[p]);
  }
  const std::vector<double> exact = nearest_by_full_solves(mesh, at);
  // A march stopped at a region's edge misses the triangle updates across
  // it and takes an edge's instead: a fraction of an edge too long there
  // (measured: 0.18 edges at worst after the inserts alone, 0.21 after the
  // removals too; 0.0015 edges on average).
  double worst = 0, sum = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    worst = std::max(worst, std::abs(double(voronoi.distance(v)) - exact[v]));
    sum += std::abs(double(voronoi.distance(v)) - exact[v]);
    // The owner is a particle at (about) that distance.
    ASSERT_NE(voronoi.owner(v), ParticleVoronoi::kNoParticle);
    EXPECT_EQ(*voronoi.vertex_of(voronoi.owner(v)), at[voronoi.owner(v)]);
  }
  EXPECT_LE(worst, 0.3 * mesh.mean_edge_length()) << "largest difference from the full solves";
  EXPECT_LE(sum / double(mesh.vertex_count()), 0.01 * mesh.mean_edge_length()) << "mean difference";
  for (std::uint32_t p = 0; p < kParticles; ++p) {
    EXPECT_EQ(voronoi.distance(at[p]), 0.0f);
    EXPECT_EQ(voronoi.owner(at[p]), p);
  }
  // The farthest vertex is the largest distance, ties to the smaller id.
  VertexId farthest = 0;
  for (VertexId v = 1; v < mesh.vertex_count(); ++v) {
    if (voronoi.distance(v) > voronoi.distance(farthest)) farthest = v;
  }
  EXPECT_EQ(voronoi.farthest(), farthest);
}

TEST(ParticleVoronoi, RemovingTheOnlyParticleOfAComponentEmptiesIt) {
  const SurfaceMesh mesh = committed("two_pieces.off");
  const auto solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  ParticleVoronoi voronoi(mesh, *solver, 2);
  VertexId other = 0;
  while (mesh.component_of(other) == mesh.component_of(0)) ++other;
  voronoi.insert(0, 0);
  voronoi.insert(1, other);
  voronoi.remove(1);
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(std::isinf(voronoi.distance(v)), mesh.component_of(v) != mesh.component_of(0)) << v;
  }
  EXPECT_EQ(mesh.component_of(*voronoi.farthest()), mesh.component_of(other));
}

TEST(MidpointRefinement, IsTheInputSurfaceWithEachVertexPlacedOnIt) {
  const SurfaceMesh input = committed("atrium.off");
  for (unsigned levels : {0u, 1u, 2u}) {
    const RefinedMesh refined = refine_by_midpoints(input, levels);
    EXPECT_EQ(refined.mesh.vertex_count(), refined_vertex_count(input, levels));
    EXPECT_EQ(refined.mesh.triangle_count(), input.triangle_count() << (2 * levels));
    EXPECT_NEAR(refined.mesh.area(), input.area(), 1e-9 * input.area());
    EXPECT_EQ(refined.mesh.boundary_vertex_count() == 0, input.boundary_vertex_count() == 0);
    EXPECT_EQ(refined.mesh.component_count(), input.component_count());
    for (VertexId v = 0; v < refined.mesh.vertex_count(); ++v) {
      const SurfaceLocation& on = refined.on_input[v];
      const Triangle& corners = input.triangles()[on.triangle];
      if (v < input.vertex_count()) {
        ASSERT_EQ(distance(refined.mesh.positions()[v], input.positions()[v]), 0.0) << "an input vertex moved";
      }
      Vec3 at{0, 0, 0};
      double sum = 0;
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(on.weights[k], 0.0);
        sum += on.weights[k];
        at = at + on.weights[k] * input.positions()[corners[k]];
      }
      ASSERT_NEAR(sum, 1.0, 1e-12);
      ASSERT_LE(distance(at, refined.mesh.positions()[v]), 1e-12 * (1 + input.mean_edge_length())) << v;
      // Its point is the one its weights give.
      ASSERT_LE(distance(on.at, at), 1e-12 * (1 + input.mean_edge_length())) << v;
    }
  }
}

// Where edges are long: every edge ends no longer than asked, the mesh stays
// conforming (a closed mesh keeps no boundary, so no edge lost its twin),
// each vertex lies on the input where its weights say, and on a vertex of
// the uniform refinement with as many rounds.
TEST(MidpointRefinement, SplittingLongEdgesConformsAndStaysOnTheSurface) {
  const SurfaceMesh input = committed("torus.off");
  for (const double longest : {0.6 * input.mean_edge_length(), 0.3 * input.mean_edge_length()}) {
    const RefinedMesh refined = refine_long_edges(input, longest, 10'000'000);
    const SurfaceMesh& mesh = refined.mesh;
    EXPECT_GT(refined.levels, 0u);
    EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
    EXPECT_EQ(mesh.component_count(), input.component_count());
    EXPECT_NEAR(mesh.area(), input.area(), 1e-9 * input.area());
    for (const Triangle& t : mesh.triangles()) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_LE(distance(mesh.positions()[t[k]], mesh.positions()[t[(k + 1) % 3]]), longest);
      }
    }
    const RefinedMesh uniform = refine_by_midpoints(input, refined.levels);
    for (VertexId v = 0; v < mesh.vertex_count(); v += 7) {
      const SurfaceLocation& on = refined.on_input[v];
      const Triangle& corners = input.triangles()[on.triangle];
      Vec3 at{0, 0, 0};
      for (int k = 0; k < 3; ++k) at = at + on.weights[k] * input.positions()[corners[k]];
      ASSERT_LE(distance(at, mesh.positions()[v]), 1e-12) << v;
    }
    std::vector<Vec3> sample;
    for (VertexId v = 0; v < mesh.vertex_count(); v += 7) sample.push_back(mesh.positions()[v]);
    EXPECT_LE(snap_to_vertices(uniform.mesh, sample).largest_snap, 1e-12);
  }
  // The cap is decided before a round: the mesh never passes it.
  const RefinedMesh capped = refine_long_edges(input, 0.1 * input.mean_edge_length(), 20'000);
  EXPECT_LE(capped.mesh.vertex_count(), 20'000u);
  EXPECT_GT(capped.mesh.vertex_count(), input.vertex_count());
}

struct Evenness {
  double cv, rho, cover;
};

Evenness measure(const SurfaceMesh& mesh, const std::vector<VertexId>& positions) {
  const double radius = 3 * hexagonal_spacing(mesh.area(), positions.size());
  const LocalDistances balls(mesh, {radius, GeodesicMethod::fast_marching, std::uint64_t{1} << 30, 0, true, std::nullopt});
  const EnergyParams energy{Potential::exp, default_sigma(Potential::exp, mesh.area(), positions.size())};
  const auto quality = measure_quality(mesh, balls, positions, energy,
                                       distance_to_nearest_particle(mesh, GeodesicMethod::fast_marching, positions),
                                       true);
  return {*quality.nn_cv, *quality.rho, *quality.cover};
}

// On closed surfaces: nn-CV and rho improve on the farthest start, cover
// stays within 1.1x of it, and the same start gives the same bits.
class SpreadImproves : public ::testing::TestWithParam<const char*> {};

TEST_P(SpreadImproves, OnTheFarthestStart) {
  const SurfaceMesh input = committed(GetParam());
  constexpr std::size_t kParticles = 256;
  RunRequest request;  // the working mesh a run would take
  request.particles = kParticles;
  const RunPlan plan = plan_run(input, request);
  const RefinedMesh working = build_working_mesh(input, plan.spread->working_mesh);
  const auto solver = make_geodesic_solver(working.mesh, GeodesicMethod::fast_marching);
  const auto start = place_particles(working.mesh, {Init::farthest, kParticles, 1, std::nullopt});
  const double min_gain = kSpreadMinGain * hexagonal_spacing(input.area(), kParticles);
  const double stall_gain = kSpreadStallGain * hexagonal_spacing(input.area(), kParticles);
  const SpreadOutcome spread = optimize_farthest_points(working.mesh, *solver, start, 100, min_gain, stall_gain, true);
  ASSERT_TRUE(spread.converged || spread.cycled || spread.stalled);
  EXPECT_EQ(std::set<VertexId>(spread.positions.begin(), spread.positions.end()).size(), kParticles);
  const Evenness before = measure(working.mesh, start), after = measure(working.mesh, spread.positions);
  EXPECT_LT(after.cv, 0.75 * before.cv);
  EXPECT_GT(after.rho, before.rho + 0.03);
  EXPECT_LE(after.cover, 1.1 * before.cover);
  // The smallest spacing does not shrink from one sweep to the next, but
  // for fast marching's noise (one-sided distances: up to 2e-3 relative measured).
  for (std::size_t k = 1; k < spread.sweeps.size(); ++k) {
    EXPECT_GE(spread.sweeps[k].min_spacing, (1 - 1e-2) * spread.sweeps[k - 1].min_spacing) << "sweep " << k;
  }
  // Every particle decides in the first sweep; a later one asks only those
  // whose surroundings changed, so the last asks fewer than all.
  ASSERT_GE(spread.sweeps.size(), 3u);
  EXPECT_EQ(spread.sweeps.front().visited, kParticles);
  EXPECT_LT(spread.sweeps.back().visited, kParticles / 2);
  for (const SweepRecord& sweep : spread.sweeps) EXPECT_LE(sweep.moved, sweep.visited);
  const SpreadOutcome again = optimize_farthest_points(working.mesh, *solver, start, 100, min_gain, stall_gain, true);
  EXPECT_EQ(again.positions, spread.positions);
}

INSTANTIATE_TEST_SUITE_P(ClosedMeshes, SpreadImproves, ::testing::Values("sphere.off", "torus.off", "atrium.off"), stem);

// The run's choices: the default is spread on the input with its long
// edges split; a paper-only option implies paper; spread refuses
// the paper's options by name.
TEST(SpreadPlan, DefaultsAndImpliedMethod) {
  const SurfaceMesh mesh = committed("torus.off");
  RunRequest request;
  request.mesh_label = "torus.off";
  request.particles = 200;
  RunPlan plan = plan_run(mesh, request);
  EXPECT_EQ(plan.method, Method::spread);
  EXPECT_EQ(plan.method_from, "default");
  ASSERT_TRUE(plan.spread);
  const WorkingMeshPlan& working = plan.spread->working_mesh;
  EXPECT_DOUBLE_EQ(working.longest_edge, kSpreadLongestEdge * hexagonal_spacing(mesh.area(), 200));
  EXPECT_GE(working.max_vertices, mesh.vertex_count());
  EXPECT_EQ(working.levels, 0u);  // no midpoint rounds unless asked for: the long edges alone

  EXPECT_FALSE(working.capped);
  request.vertices_per_particle = 100;  // asked for: more rounds
  EXPECT_GT(plan_run(mesh, request).spread->working_mesh.levels, working.levels);
  EXPECT_FALSE(plan_run(mesh, request).spread->working_mesh.capped);
  request.vertices_per_particle = 1e12;  // more than the cap allows: said, not silent
  request.quiet = true;
  const WorkingMeshPlan capped = plan_run(mesh, request).spread->working_mesh;
  EXPECT_TRUE(capped.capped);
  EXPECT_LE(refined_vertex_count(mesh, capped.levels), capped.max_vertices);
  EXPECT_GT(refined_vertex_count(mesh, capped.levels + 1), capped.max_vertices);
  request.quiet = false;
  request.vertices_per_particle.reset();
  request.longest_edge = 0.5;  // asked for (correspond's template): longer edges kept
  EXPECT_DOUBLE_EQ(plan_run(mesh, request).spread->working_mesh.longest_edge,
                   0.5 * hexagonal_spacing(mesh.area(), 200));
  request.longest_edge.reset();

  request.scheme = Scheme::sequential;
  plan = plan_run(mesh, request);
  EXPECT_EQ(plan.method, Method::paper);
  EXPECT_EQ(plan.method_from, "--scheme implies paper");

  request.method = Method::spread;
  try {
    plan_run(mesh, request);
    FAIL() << "spread took --scheme";
  } catch (const std::exception& error) {
    EXPECT_STREQ(error.what(), "--scheme applies to --method paper");
  }
}

// The refusal both front ends used to make before planning, made by
// plan_run for every caller and for either method.
TEST(PlanRun, RefusesACutoffWithTheDenseTable) {
  const SurfaceMesh mesh = committed("torus.off");
  RunRequest request = quiet_run_request("torus.off", 8);
  request.distances.kind = StoreKind::dense;
  EXPECT_NO_THROW(plan_run(mesh, request));
  request.distances.cutoff = 6;
  for (const Method method : {Method::spread, Method::paper}) {
    request.method = method;
    try {
      plan_run(mesh, request);
      FAIL() << "a cutoff with the dense table was planned";
    } catch (const std::exception& error) {
      EXPECT_STREQ(error.what(), "--cutoff applies to --distances local and auto");
    }
  }
  request.distances.kind = StoreKind::local;
  EXPECT_NO_THROW(plan_run(mesh, request));
}

TEST(SpreadRun, LandsEveryParticleOnTheInputSurfaceAndMeasuresOnTheWorkingMesh) {
  const SurfaceMesh mesh = committed("atrium.off");
  const RunRequest request = quiet_run_request("atrium.off", 300);
  const RunResult result = run_pipeline(mesh, request);
  ASSERT_TRUE(result.spread);
  EXPECT_EQ(result.distance_to_nearest.size(), result.spread->working->mesh.vertex_count());
  ASSERT_EQ(result.outcome.positions.size(), 300u);
  EXPECT_FALSE(result.spread->sweeps.empty());
  EXPECT_LT(*result.quality.nn_cv, 0.07);
  EXPECT_GT(*result.quality.rho, 0.75);
}

// The default working mesh is the input with its long edges split, no
// midpoint rounds over the whole: on the torus at n = 1,024, 25,630
// vertices where the rounds to 24 a particle gave 97,017 (95 a particle),
// each edge within kSpreadLongestEdge spacings (before the kept points are
// inserted), and the relaxation as even as it was (rho 0.952, nn_cv 0.0044;
// 0.953, 0.0039 before).
TEST(SpreadRun, TheDefaultWorkingMeshSplitsOnlyTheLongEdges) {
  const SurfaceMesh mesh = committed("torus.off");
  constexpr std::size_t kParticles = 1024;
  const RunResult result = run_pipeline(mesh, quiet_run_request("torus.off", kParticles));
  ASSERT_TRUE(result.spread);
  EXPECT_EQ(result.plan.spread->working_mesh.levels, 0u);
  ASSERT_LT(result.spread->relaxation.kept, result.spread->relaxation.candidates.size());
  const SurfaceMesh& working = result.spread->working->mesh;
  EXPECT_LE(working.vertex_count(), 30 * kParticles);
  EXPECT_GE(working.vertex_count(), 10 * kParticles);
  const RefinedMesh unmoved = build_working_mesh(mesh, result.plan.spread->working_mesh);
  const double longest = kSpreadLongestEdge * hexagonal_spacing(mesh.area(), kParticles);
  for (const Triangle& t : unmoved.mesh.triangles()) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_LE(distance(unmoved.mesh.positions()[t[k]], unmoved.mesh.positions()[t[(k + 1) % 3]]), longest);
    }
  }
  EXPECT_LE(working.vertex_count(), unmoved.mesh.vertex_count() + kParticles);  // and the kept points, vertices
  EXPECT_GT(*result.quality.rho, 0.94);
  EXPECT_LT(*result.quality.nn_cv, 0.01);
}

}  // namespace
}  // namespace meshparticles::testing
