// The evening's geodesic Voronoi diagram on the device
// (particles/device_surface_voronoi, kernels/surface_voronoi.cl) against the
// host's (particles/surface_voronoi, fast marching), its oracle, on the
// committed meshes and a CGAL mesh, at 64 and 1,024 points.
//
// Three oracles: the host's rounds (particles/surface_voronoi_rounds, the
// same step written once: the same bits), the host's diagram by the fast
// iterative method (the same updates, pushed in another order) and by fast
// marching (what the evening uses on the host). These two solvers agree
// with the device to their accuracy, not bit for bit
// (the bounds and why: kSameMethod, kFastMarching): distances on average,
// and at a small share of vertices by up to an edge; owners except at a
// small share of vertices, each where the device's point is within the
// distances' bound as near as the host's by single solves from both (a
// near-tie); covering radii. And the same bits from two diagrams of the same
// points, on one solver and on two.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "common/random.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_on_triangle.hpp"
#include "mesh/surface_walk.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/device_surface_voronoi.hpp"
#include "particles/farthest_point_optimization.hpp"
#include "particles/initial_placement.hpp"
#include "particles/local_farthest_points.hpp"
#include "particles/particle_params.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/surface_voronoi_rounds.hpp"
#include "pipeline/point_set_measurement.hpp"
#include "pipeline/run_pipeline.hpp"
#include "quality/distribution_quality.hpp"
#include "evening_start.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {


std::vector<SurfaceLocation> random_surface_points(const SurfaceMesh& mesh, std::size_t count, std::uint64_t seed) {
  SplitMix64 random(seed);
  std::vector<SurfaceLocation> points;
  for (std::size_t k = 0; k < count; ++k) {
    SurfaceLocation p;
    p.triangle = std::uint32_t(random.below(mesh.triangles().size()));
    double a = random.uniform();
    double b = random.uniform();
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    p.weights = {a, b, 1 - a - b};
    const auto& corners = mesh.triangles()[p.triangle];
    p.at = at_weights(p.weights, mesh.positions()[corners[0]], mesh.positions()[corners[1]],
                      mesh.positions()[corners[2]]);
    points.push_back(p);
  }
  return points;
}

struct VoronoiAgreement {
  std::size_t compared = 0, owners_changed = 0, only_one_reached = 0, off_by_a_percent = 0;
  double sum_relative = 0, worst_relative = 0, cover_relative = 0;
  double widest_tie = 0;  // at a vertex of another owner: |d(device's) - d(host's)| / max(h, edge), single solves
};

// Point i's distance at v, alone: a march from its triangle's corners, each at
// its straight distance (the seeding of both diagrams), out to `radius`.
double distance_from_point(const SurfaceMesh& mesh, const GeodesicSolver& solver, const SurfaceLocation& point,
                           VertexId v, double radius) {
  std::vector<VertexId> corners;
  std::vector<double> starts;
  for (const VertexId c : mesh.triangles()[point.triangle]) {
    corners.push_back(c);
    starts.push_back(distance(point.at, mesh.positions()[c]));
  }
  SolverScratch scratch;
  std::vector<std::pair<VertexId, float>> within;
  solver.solve_ball_from(corners, starts, radius, scratch, within);
  for (const auto& [w, d] : within) {
    if (w == v) return d;
  }
  return std::numeric_limits<double>::infinity();
}

// The device's diagram against a host's, vertex by vertex; `solver` measures
// the single points at the vertices whose owners differ.
VoronoiAgreement compare_voronoi(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                 std::span<const SurfaceLocation> points, const SurfaceVoronoi& device,
                                 const SurfaceVoronoi& host) {
  VoronoiAgreement agreement;
  const double floor = mesh.mean_edge_length();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    const double d = device.distance[v], h = host.distance[v];
    if (std::isinf(h) || std::isinf(d)) {
      agreement.only_one_reached += std::size_t(std::isinf(h) != std::isinf(d) ||
                                                (device.owner[v] == SurfaceVoronoi::kNoPoint) !=
                                                    (host.owner[v] == SurfaceVoronoi::kNoPoint));
      continue;
    }
    const double scale = std::max(h, floor);
    const double relative = std::abs(d - h) / scale;
    ++agreement.compared;
    agreement.sum_relative += relative;
    agreement.worst_relative = std::max(agreement.worst_relative, relative);
    agreement.off_by_a_percent += std::size_t(relative > 0.01);
    if (device.owner[v] == host.owner[v]) continue;
    ++agreement.owners_changed;
    if (device.owner[v] >= points.size() || host.owner[v] >= points.size()) {
      ADD_FAILURE() << "vertex " << v << " at a finite distance belongs to no point: " << device.owner[v] << ", host "
                    << host.owner[v];
      continue;
    }
    const double radius = 2 * std::max(d, h) + 4 * floor;
    const double from_device_owner = distance_from_point(mesh, solver, points[device.owner[v]], v, radius);
    const double from_host_owner = distance_from_point(mesh, solver, points[host.owner[v]], v, radius);
    agreement.widest_tie = std::max(agreement.widest_tie, (from_device_owner - from_host_owner) / scale);
  }
  agreement.cover_relative = std::abs(device.cover() - host.cover()) / host.cover();
  return agreement;
}

struct VoronoiTolerance {
  double worst_relative, mean_relative, off_share, owner_change_share, tie, cover_relative;
};
// Distances in units of max(h, the mean edge). Where two points' regions
// meet, a triangle update needs both corners of one owner (fast_marching.cpp):
// a border vertex may keep an edge update, up to most of an edge long, and
// which border triangles qualify depends on the order the solver fills them
// in. So a few vertices differ by up to an edge (measured, worst of 18 cases:
// 0.65, camel at 1,024, 10 vertices a point), the rest agree: the means and
// shares are what hold the diagram. Against the host's fim (the same updates
// in another order): mean 0.0022, 2.5% of the vertices off by over 1%
// (camel), 0.9% change owner; against fast marching (the evening's host
// diagram, whose start from a point's corners overestimates near the point,
// up to 27% on the flat patch where the device and fim give the straight
// line): mean 0.011, 14% off by 1%, 2.6% change owner (camel). `tie`: at a
// vertex the device gives another point, how much farther that point is, by
// single solves from each (measured: 0.43). Covers: 2.0% (atrium, torus).
// Each bound is about twice the worst measured.
const VoronoiTolerance kSameMethod{1.0, 0.005, 0.05, 0.02, 1.0, 0.04};
const VoronoiTolerance kFastMarching{1.0, 0.025, 0.25, 0.05, 1.0, 0.04};

void expect_within(const VoronoiAgreement& agreement, const VoronoiTolerance& tolerance, std::size_t vertices,
                   const std::string& oracle) {
  SCOPED_TRACE("against the host's " + oracle);
  EXPECT_EQ(agreement.only_one_reached, 0u) << "a vertex reached by one diagram only";
  EXPECT_LE(agreement.worst_relative, tolerance.worst_relative);
  EXPECT_LE(agreement.sum_relative / double(std::max<std::size_t>(agreement.compared, 1)), tolerance.mean_relative);
  EXPECT_LE(double(agreement.owners_changed), tolerance.owner_change_share * double(vertices))
      << agreement.owners_changed << " of " << vertices << " vertices change owner";
  EXPECT_LE(double(agreement.off_by_a_percent), tolerance.off_share * double(vertices));
  EXPECT_LE(agreement.widest_tie, tolerance.tie) << "a vertex changes owner where its two points are not near-tied";
  EXPECT_LE(agreement.cover_relative, tolerance.cover_relative);
}

void print_agreement(const std::string& what, const VoronoiAgreement& a) {
  std::cout << "[ info ] " << what << ": worst " << a.worst_relative << ", mean "
            << a.sum_relative / double(std::max<std::size_t>(a.compared, 1)) << " relative, " << a.off_by_a_percent
            << " off by 1%; " << a.owners_changed << " owners changed (widest tie " << a.widest_tie << "); cover "
            << a.cover_relative << "\n";
}

void expect_device_matches_host(const SurfaceMesh& mesh, const std::string& name) {
  const auto marching = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  const auto iterative = make_geodesic_solver(mesh, GeodesicMethod::fast_iterative);
  DeviceSurfaceVoronoi device(mesh, select_device(""));
  for (const std::size_t n : {64, 1024}) {
    SCOPED_TRACE(name + ", n = " + std::to_string(n));
    const std::vector<SurfaceLocation> points = random_surface_points(mesh, n, 59 + n);
    SolverScratch scratch;
    const SurfaceVoronoi first = device.diagram(points);
    const VoronoiAgreement same_method =
        compare_voronoi(mesh, *iterative, points, first, surface_voronoi(mesh, *iterative, points, scratch));
    const VoronoiAgreement evening =
        compare_voronoi(mesh, *marching, points, first, surface_voronoi(mesh, *marching, points, scratch));
    print_agreement(name + " n=" + std::to_string(n) + " vs fim", same_method);
    print_agreement(name + " n=" + std::to_string(n) + " vs fmm", evening);
    expect_within(same_method, kSameMethod, mesh.vertex_count(), "fast iterative method");
    expect_within(evening, kFastMarching, mesh.vertex_count(), "fast marching");
    const SurfaceVoronoi second = device.diagram(points);
    EXPECT_EQ(first.distance, second.distance) << "two diagrams of the same points differ";
    EXPECT_EQ(first.owner, second.owner);
    // The host's rounds, on one thread and on two: the device's bits.
    for (const unsigned threads : {1u, 2u}) {
      const SurfaceVoronoi host = SurfaceVoronoiRounds(mesh, threads).diagram(points);
      EXPECT_EQ(host.distance, first.distance) << "the host's rounds on " << threads << " threads";
      EXPECT_EQ(host.owner, first.owner) << "the host's rounds on " << threads << " threads";
    }
  }
}

class DeviceVoronoiCommitted : public ::testing::TestWithParam<const char*> {};

TEST_P(DeviceVoronoiCommitted, IsTheHostsDiagramToTheSolversAccuracy) {
  expect_device_matches_host(committed(GetParam()), GetParam());
}

INSTANTIATE_TEST_SUITE_P(CommittedMeshes, DeviceVoronoiCommitted,
                         ::testing::ValuesIn(kCommittedMeshes), stem);

TEST(DeviceVoronoi, IsTheHostsDiagramOnACgalMesh) {
  const std::optional<SurfaceMesh> camel = cgal_mesh("camel.off");
  if (camel) expect_device_matches_host(*camel, "camel");
}

// The diagram alone, timed: host (fast marching, one thread) against the
// device, the figures of docs/PERFORMANCE.md ("spread's diagrams and measurement on the
// device"), and held to the host as above. $MESHPARTICLES_VORONOI_MESH (default
// the committed atrium) and $MESHPARTICLES_VORONOI_N (default 1,024) choose the case.
TEST(DeviceVoronoi, TimedAgainstTheHost) {
  std::vector<std::string> warnings;
  const char* given = std::getenv("MESHPARTICLES_VORONOI_MESH");
  const SurfaceMesh mesh = given ? read_mesh(given, warnings) : committed("atrium.off");
  const char* count = std::getenv("MESHPARTICLES_VORONOI_N");
  const std::size_t n = count ? std::stoul(count) : 1024;
  const std::vector<SurfaceLocation> points = random_surface_points(mesh, n, 5);
  const auto marching = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  constexpr int kRepeats = 5;
  const auto ms_since = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  SurfaceVoronoi host = surface_voronoi(mesh, *marching, points, scratch);
  auto started = std::chrono::steady_clock::now();
  for (int k = 0; k < kRepeats; ++k) host = surface_voronoi(mesh, *marching, points, scratch);
  const double host_ms = ms_since(started) / kRepeats;
  started = std::chrono::steady_clock::now();
  DeviceSurfaceVoronoi device(mesh, select_device(""));
  const double setup_ms = ms_since(started);
  const SurfaceVoronoi first = device.diagram(points);
  started = std::chrono::steady_clock::now();
  for (int k = 0; k < kRepeats; ++k) EXPECT_EQ(device.diagram(points).owner, first.owner);
  const double device_ms = ms_since(started) / kRepeats;
  expect_within(compare_voronoi(mesh, *marching, points, first, host), kFastMarching, mesh.vertex_count(),
                "fast marching");
  std::cout << "[ info ] " << mesh.vertex_count() << " vertices, n = " << n << ": host " << host_ms
            << " ms a diagram, device " << device_ms << " ms (" << device.statistics().rounds / (kRepeats + 1)
            << " rounds; set-up once per mesh " << setup_ms << " ms) on " << device.device_name() << "\n";
}

TEST(DeviceVoronoi, ASecondSolverGivesTheSameBits) {
  const SurfaceMesh mesh = committed("atrium.off");
  const std::vector<SurfaceLocation> points = random_surface_points(mesh, 1024, 7);
  DeviceSurfaceVoronoi one(mesh, select_device("")), other(mesh, select_device(""));
  const SurfaceVoronoi a = one.diagram(points), b = other.diagram(points);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.owner, b.owner);
}

// The evening's diagrams after its first sweep: the last one brought up to
// date where points moved (DeviceSurfaceVoronoi::update), against the host's
// diagram anew by fast marching (the evening's on the host) and the
// device's anew. A third of the points each step half a spacing toward the
// next, and one jumps across the mesh.
void expect_update_matches(const SurfaceMesh& mesh, const std::string& name, std::size_t n) {
  SCOPED_TRACE(name + ", n = " + std::to_string(n));
  const EveningStart start = evening_start(mesh, n);
  std::vector<SurfaceLocation> points = start.from;
  DeviceSurfaceVoronoi device(mesh, select_device(""));
  SurfaceVoronoiRounds rounds(mesh, 2);
  SurfaceVoronoi updated = device.diagram(points);
  SurfaceVoronoi updated_on_host = rounds.diagram(points);
  const SurfaceVoronoi before = updated;
  device.update(points, std::vector<char>(points.size(), 0), updated);
  EXPECT_EQ(updated.distance, before.distance);  // nothing moved: nothing changes
  EXPECT_EQ(updated.owner, before.owner);

  const std::vector<char> moved = move_a_third_and_one_far(mesh, start.d_hex, points);
  const std::size_t rounds_before = device.statistics().rounds;
  device.update(points, moved, updated);
  const std::size_t update_rounds = device.statistics().rounds - rounds_before;
  rounds.update(points, moved, updated_on_host);
  EXPECT_EQ(updated_on_host.distance, updated.distance) << "the host's rounds, updated";
  EXPECT_EQ(updated_on_host.owner, updated.owner);
  EXPECT_EQ(rounds.statistics().rounds, device.statistics().rounds) << "rounds that changed something";
  const SurfaceVoronoi anew = device.diagram(points);
  const std::size_t anew_rounds = device.statistics().rounds - rounds_before - update_rounds;
  EXPECT_EQ(device.statistics().diagrams, 4u);
  EXPECT_LE(update_rounds, anew_rounds);  // fewer on the evening's finer mesh and shorter moves (bull at 1,024: 246 against 1,120)

  const auto marching = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  const SurfaceVoronoi host = surface_voronoi(mesh, *marching, points, scratch);
  const VoronoiAgreement from_update = compare_voronoi(mesh, *marching, points, updated, host);
  const VoronoiAgreement from_anew = compare_voronoi(mesh, *marching, points, anew, host);
  print_agreement(name + " n=" + std::to_string(n) + ", updated (" + std::to_string(update_rounds) +
                      " rounds) vs fmm", from_update);
  print_agreement(name + " n=" + std::to_string(n) + ", anew (" + std::to_string(anew_rounds) + " rounds) vs fmm",
                  from_anew);
  expect_within(from_update, kFastMarching, mesh.vertex_count(), "fast marching");
  // Not the anew diagram's bits: rounds go by edges, not by distance, so
  // where a point's front passes a vertex that later goes to another point
  // the vertices beyond keep the lower value it brought (the same owner's
  // corners no longer justify it), and the update starts where the
  // unmoved regions are settled. Measured: as near the host's as anew or
  // nearer (mean relative: torus at 256 0.0019 against 0.0025, atrium at
  // 1,024 0.00065 against 0.00069, bull 0.0053 against 0.0079; covers:
  // torus 1.7% off against 5.5%, the others the same). Without the rims
  // started or the moved points' regions emptied, hundreds of vertices
  // change owner.
  EXPECT_LE(from_update.sum_relative / double(from_update.compared),
            1.25 * from_anew.sum_relative / double(from_anew.compared));
  EXPECT_LE(from_update.cover_relative, from_anew.cover_relative + 0.01);
}

TEST(DeviceVoronoi, AnUpdateAfterMovesIsAsNearTheHostsAsADiagramAnew) {
  expect_update_matches(committed("torus.off"), "torus", 256);
  expect_update_matches(committed("atrium.off"), "atrium", 1024);
  if (const std::optional<SurfaceMesh> bull = cgal_mesh("bull.off")) expect_update_matches(*bull, "bull", 1024);
}

}  // namespace
}  // namespace meshparticles::testing

namespace meshparticles::testing {
namespace {

// spread's evening (particles/local_farthest_points) from the sweeps'
// vertices of a farthest start, its diagrams on the host or on `device`.
EveningOutcome evening_from_sweeps(const SurfaceMesh& mesh, std::size_t particles, DeviceSurfaceVoronoi* device,
                                   std::size_t sweeps = 40) {
  const EveningStart s = evening_start(mesh, particles);
  const double d_hex = s.d_hex;
  return even_out(mesh, *s.solver, s.from, {sweeps, d_hex, 1e-3 * d_hex, 1e-4 * d_hex, 1.1 * s.start_cover}, 2, true,
                  {device, nullptr});
}

DistributionQuality evened_quality(const SurfaceMesh& mesh, const EveningOutcome& outcome) {
  PointSetsRequest request;
  request.names = {"evened"};
  request.points.emplace_back();
  for (const SurfaceLocation& p : outcome.points) request.points.back().push_back(p.at);
  request.geodesics.quiet = true;
  return measure_point_sets(mesh, request).sets[0].quality;
}

class DeviceEvening : public ::testing::TestWithParam<const char*> {};

TEST_P(DeviceEvening, EvensAsTheHostDoes) {
  const SurfaceMesh mesh = committed(GetParam());
  DeviceSurfaceVoronoi device(mesh, select_device(""));
  for (const std::size_t n : {64, 256}) {
    SCOPED_TRACE(std::string(GetParam()) + ", n = " + std::to_string(n));
    const double d_hex = hexagonal_spacing(mesh.area(), n);
    auto in_the_same_place = [&](const EveningOutcome& a, const EveningOutcome& b) {
      std::size_t same = 0;
      for (std::size_t i = 0; i < n; ++i) same += std::size_t(distance(a.points[i].at, b.points[i].at) < 1e-3 * d_hex);
      return same;
    };
    // The first sweep, from the same start: the same moves but where a
    // near-tie of the two diagrams falls the other way.
    const EveningOutcome host_first = evening_from_sweeps(mesh, n, nullptr, 1);
    const EveningOutcome device_first = evening_from_sweeps(mesh, n, &device, 1);
    const std::size_t same_after_one = in_the_same_place(host_first, device_first);
    EXPECT_NEAR(double(device_first.sweeps[0].moved), double(host_first.sweeps[0].moved),
                0.06 * double(host_first.sweeps[0].moved) + 2);
    EXPECT_GE(same_after_one, 9 * n / 10);
    const EveningOutcome host = evening_from_sweeps(mesh, n, nullptr);
    const EveningOutcome on_device = evening_from_sweeps(mesh, n, &device);
    EXPECT_TRUE(host.diagrams.device.empty());
    EXPECT_EQ(on_device.diagrams.device, device.device_name());
    EXPECT_EQ(on_device.diagrams.count, on_device.sweeps.size() + 1);
    std::size_t host_moves = 0, device_moves = 0;
    for (const auto& s : host.sweeps) host_moves += s.moved;
    for (const auto& s : on_device.sweeps) device_moves += s.moved;
    const std::size_t same_place = in_the_same_place(host, on_device);
    const DistributionQuality h = evened_quality(mesh, host), d = evened_quality(mesh, on_device);
    // After the first sweep the two go their own ways: where a near-tie of
    // the two diagrams falls the other way, a region or a neighbour list
    // differs, one move with it, and every sweep after it. The evening makes
    // many small moves (0.25.0, to each cavity's centre: sphere at 256, 4,110
    // in 27 sweeps), so few particles may end in the same place (measured:
    // 7 of 64 on the sphere, 0 of 256 on the torus): the set is as even,
    // not the same. Measured at 0.25.0: moves within 17% (torus at 256),
    // nn_min 0.3%, nn_cv 3%, cover 1.5%. Bounds near twice the moves'.
    EXPECT_NEAR(double(device_moves), double(host_moves), 0.25 * double(host_moves));
    EXPECT_NEAR(*d.nn_min, *h.nn_min, 0.02 * *h.nn_min);
    EXPECT_NEAR(*d.nn_cv, *h.nn_cv, 0.2 * *h.nn_cv + 0.005);
    EXPECT_NEAR(on_device.cover, host.cover, 0.12 * host.cover);
    std::cout << "[ info ] " << GetParam() << " n=" << n << ": moves " << host_moves << " / " << device_moves
              << ", same place " << same_after_one << " after one sweep, " << same_place << " at the end, first sweep's moves "
              << host_first.sweeps[0].moved << " / " << device_first.sweeps[0].moved << ", nn_min " << *h.nn_min / d_hex << " / " << *d.nn_min / d_hex
              << ", nn_cv " << *h.nn_cv << " / " << *d.nn_cv << ", cover " << host.cover / d_hex << " / "
              << on_device.cover / d_hex << "\n";
  }
}

INSTANTIATE_TEST_SUITE_P(CommittedMeshes, DeviceEvening, ::testing::Values("sphere.off", "atrium.off", "torus.off"),
                         stem);

// The whole run with --device (RunRequest::backend.device) against the
// host path on three CGAL models at 64 and 1,024 particles, and bull at
// 4,096: on the
// committed meshes spread keeps the relaxation and no evening runs
// (docs/ALGORITHM.md), on these it runs but where the relaxation is kept
// (then both paths are the same bits, the device unused). The two
// diagrams differ where two regions meet (DeviceVoronoi above), so a
// near-tie can list another neighbour and the sweeps after it go their own
// ways: as many accepted moves within 25% (and 4) and particles as even
// (measured at 0.25.0, whose evening makes many small moves: moves within
// 16%, bull at 64, 0.17.0 2.2%; rho the host's or higher; nn_cv within 4%;
// cover within 4.3%; DeviceEvening above holds the first sweep's moves to
// the host's).
// With the device's diagrams left as the first sweep found them, 7.7% to
// 21% fewer moves (1 to 16 at n = 64), and camel's rho 0.02 to 0.03 lower.
class DeviceRun : public ::testing::TestWithParam<std::tuple<const char*, std::size_t>> {};

TEST_P(DeviceRun, IsAsEvenAsTheHostsRun) {
  const auto [model, particles] = GetParam();
  const std::optional<SurfaceMesh> mesh = cgal_mesh(std::string(model) + ".off");
  if (!mesh) return;
  RunRequest request;
  request.mesh_label = std::string(model) + ".off";
  request.particles = particles;
  request.quiet = true;
  const RunResult host = run_pipeline(*mesh, request);
  request.backend.device = select_device("").index();
  const RunResult device = run_pipeline(*mesh, request);
  ASSERT_TRUE(host.spread && device.spread);
  ASSERT_EQ(host.spread->evening.has_value(), device.spread->evening.has_value());
  if (!host.spread->evening) {
    EXPECT_EQ(device.outcome.positions, host.outcome.positions);
    std::cout << "[ info ] " << model << " n=" << particles << ": the relaxation kept, no evening\n";
    return;
  }
  EXPECT_TRUE(host.spread->evening->diagrams.device.empty());
  EXPECT_EQ(device.spread->evening->diagrams.device, select_device("").name);
  EXPECT_EQ(device.device, select_device("").name);
  std::size_t host_moves = 0, device_moves = 0;
  for (const auto& s : host.spread->evening->sweeps) host_moves += s.moved;
  for (const auto& s : device.spread->evening->sweeps) device_moves += s.moved;
  EXPECT_NEAR(double(device_moves), double(host_moves), 0.25 * double(host_moves) + 4);
  EXPECT_GE(*device.quality.rho, *host.quality.rho - 0.02);
  EXPECT_LE(*device.quality.nn_cv, 1.25 * *host.quality.nn_cv);
  EXPECT_LE(*device.quality.cover, 1.1 * *host.quality.cover);  // the evening's own limit: 1.1x the start's
  std::cout << "[ info ] " << model << " n=" << particles << ": moves " << host_moves << " / " << device_moves
            << ", rho " << *host.quality.rho << " / " << *device.quality.rho << ", nn_cv " << *host.quality.nn_cv
            << " / " << *device.quality.nn_cv << ", cover " << *host.quality.cover << " / " << *device.quality.cover
            << "\n";
}

// At 4,096 bull alone (12 s of the suite's time; camel and man there are 11
// and 12 more): scripts/bench_device_voronoi.sh runs four models at 4,096.
INSTANTIATE_TEST_SUITE_P(CgalModels, DeviceRun,
                         ::testing::Values(std::make_tuple("bull", std::size_t(64)),
                                           std::make_tuple("bull", std::size_t(1024)),
                                           std::make_tuple("bull", std::size_t(4096)),
                                           std::make_tuple("camel", std::size_t(64)),
                                           std::make_tuple("camel", std::size_t(1024)),
                                           std::make_tuple("man", std::size_t(64)),
                                           std::make_tuple("man", std::size_t(1024))),
                         [](const auto& param_info) {
                           return std::string(std::get<0>(param_info.param)) + "_" + std::to_string(std::get<1>(param_info.param));
                         });

}  // namespace
}  // namespace meshparticles::testing
