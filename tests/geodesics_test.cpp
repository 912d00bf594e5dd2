// Geodesic distances against exact answers: great circles on the sphere,
// straight lines on a flat patch; and the table's invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <numeric>

#include "common/random.hpp"
#include "common/user_error.hpp"
#include "geodesics/planar_source.hpp"
#include "geodesics/distance_table.hpp"
#include "geodesics/fast_iterative.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "geodesics/memory_guard.hpp"
#include "geodesics/point_seeds.hpp"
#include "geodesics/point_source_update.hpp"
#include "geodesics/solver_factory.hpp"
#include "geodesics/triangle_stencils.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "mesh/vertex_triangles.hpp"
#include "fixtures/mesh_generator.hpp"
#include "test_files.hpp"

namespace meshparticles {
namespace {


struct ErrorStats {
  double mean = 0, p99 = 0;
};

// Relative error of `table` against `exact` over pairs farther apart than
// three mean edge lengths (closer pairs are dominated by discretisation).
template <typename Exact>
ErrorStats relative_errors(const SurfaceMesh& mesh, const DistanceTable& table, std::size_t source_stride, Exact exact) {
  std::vector<double> errors;
  const double near = 3 * mesh.mean_edge_length();
  for (VertexId u = 0; u < mesh.vertex_count(); u += VertexId(source_stride)) {
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
      const double truth = exact(mesh.positions()[u], mesh.positions()[v]);
      if (truth > near) errors.push_back(std::abs(table(u, v) - truth) / truth);
    }
  }
  ErrorStats stats;
  stats.mean = std::accumulate(errors.begin(), errors.end(), 0.0) / double(errors.size());
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(0.99 * double(errors.size())), errors.end());
  stats.p99 = errors[std::size_t(0.99 * double(errors.size()))];
  return stats;
}

double great_circle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0));  // unit sphere
}

TEST(Geodesics, SphereFastMarchingIsWithinOnePercentAndFarBetterThanDijkstra) {
  const SurfaceMesh sphere = testing::committed("sphere.off");
  const DistanceTable fmm = compute_all_pairs(sphere, GeodesicMethod::fast_marching, 0, true);
  const ErrorStats fmm_error = relative_errors(sphere, fmm, 1, great_circle);
  const DistanceTable dijkstra = compute_all_pairs(sphere, GeodesicMethod::dijkstra, 0, true);
  const ErrorStats dijkstra_error = relative_errors(sphere, dijkstra, 1, great_circle);
  std::printf("sphere, relative error vs great circles: fmm mean %.3f%% p99 %.3f%%; dijkstra mean %.3f%% p99 %.3f%%\n",
              100 * fmm_error.mean, 100 * fmm_error.p99, 100 * dijkstra_error.mean, 100 * dijkstra_error.p99);
  EXPECT_LE(fmm_error.mean, 0.010);
  EXPECT_LE(fmm_error.p99, 0.030);
  EXPECT_GT(dijkstra_error.mean, 4 * fmm_error.mean);
}

TEST(Geodesics, FlatPatchMatchesEuclideanDistance) {
  const SurfaceMesh patch = testing::committed("patch.off");
  const DistanceTable fmm = compute_all_pairs(patch, GeodesicMethod::fast_marching, 0, true);
  const ErrorStats error = relative_errors(patch, fmm, 1, [](const Vec3& a, const Vec3& b) { return distance(a, b); });
  std::printf("flat patch, relative error vs Euclidean: mean %.4f%% p99 %.4f%%\n", 100 * error.mean, 100 * error.p99);
  EXPECT_LE(error.mean, 0.010);
  EXPECT_LE(error.p99, 0.030);
}

// Worst relative excess d(a,c) / (d(a,b) + d(b,c)) - 1 over random triples.
double worst_triangle_excess(const DistanceTable& table, int triples) {
  SplitMix64 random(7);
  const auto n = table.vertex_count();
  double worst = 0;
  for (int trial = 0; trial < triples; ++trial) {
    const auto a = VertexId(random.below(n)), b = VertexId(random.below(n)), c = VertexId(random.below(n));
    worst = std::max(worst, table(a, c) / (double(table(a, b)) + table(b, c)) - 1);
  }
  return worst;
}

TEST(Geodesics, TableIsSymmetricWithZeroDiagonal) {
  const SurfaceMesh torus = testing::committed("torus.off");
  const DistanceTable table = compute_all_pairs(torus, GeodesicMethod::fast_marching, 0, true);
  const auto n = VertexId(torus.vertex_count());
  for (VertexId u = 0; u < n; ++u) {
    ASSERT_EQ(table(u, u), 0.0f);
    for (VertexId v = u + 1; v < n; ++v) {
      ASSERT_EQ(table(u, v), table(v, u));
      ASSERT_GT(table(u, v), 0.0f);
      ASSERT_TRUE(std::isfinite(table(u, v)));
    }
  }
}

TEST(Geodesics, TriangleInequalityHoldsOnRandomTriples) {
  // On the sphere within 1e-4 relative, as asked.
  const DistanceTable sphere = compute_all_pairs(testing::committed("sphere.off"), GeodesicMethod::fast_marching, 0, true);
  EXPECT_LE(worst_triangle_excess(sphere, 200000), 1e-4);
  // Where one-sided fast marching errs most - behind the torus's cut loci,
  // along the patch's boundary - a few triples in a thousand exceed 1e-4; the
  // bound met there is 1% (docs/GEODESICS.md has the measured figures).
  const DistanceTable torus = compute_all_pairs(testing::committed("torus.off"), GeodesicMethod::fast_marching, 0, true);
  EXPECT_LE(worst_triangle_excess(torus, 200000), 1e-2);
  const DistanceTable patch = compute_all_pairs(testing::committed("patch.off"), GeodesicMethod::fast_marching, 0, true);
  EXPECT_LE(worst_triangle_excess(patch, 200000), 1e-2);
}

TEST(Geodesics, DifferentComponentsAreInfinitelyFarAndNothingIsNaN) {
  const SurfaceMesh pieces = generate_mesh("two_pieces");
  const DistanceTable table = compute_all_pairs(pieces, GeodesicMethod::fast_marching, 0, true);
  for (VertexId u = 0; u < 8; ++u) {
    for (VertexId v = 0; v < 8; ++v) {
      ASSERT_FALSE(std::isnan(table(u, v)));
      if (pieces.component_of(u) == pieces.component_of(v)) {
        EXPECT_TRUE(std::isfinite(table(u, v)));
      } else {
        EXPECT_EQ(table(u, v), INFINITY);
      }
    }
  }
  // Within a tetrahedron all vertices are neighbours: exact edge lengths.
  EXPECT_NEAR(table(0, 1), 2 * std::sqrt(2.0), 1e-6);
}

TEST(Geodesics, HighValenceAndObtuseTrianglesStayAccurate) {
  // Apex to apex on the 24-sided bipyramid: unfolded, the straight path
  // crosses a ring edge at its midpoint, cos(pi/24) from the axis. Every
  // face has a 7.5-degree apex angle, so the path crosses long thin faces.
  const SurfaceMesh bipyramid = generate_mesh("high_valence");
  const DistanceTable table = compute_all_pairs(bipyramid, GeodesicMethod::fast_marching, 0, true);
  const double midpoint_radius = std::cos(std::numbers::pi / 24);
  EXPECT_NEAR(table(0, 1), 2 * std::sqrt(1 + midpoint_radius * midpoint_radius), 1e-5);
}

// From ring vertex 0 the bipyramid is symmetric about the plane through it
// and the axis (ring vertex k mirrors 24 - k). The apexes list 24 triangles
// each, more than fast marching looks at in one batch, so a triangle skipped
// or updated twice on one side shows as a broken mirror.
TEST(Geodesics, HighValenceFansAreUpdatedAllRound) {
  const SurfaceMesh bipyramid = generate_mesh("high_valence");
  const auto solver = make_geodesic_solver(bipyramid, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  std::vector<double> distances(bipyramid.vertex_count());
  constexpr VertexId kFirstRing = 2, kSides = 24;
  solver->solve(kFirstRing, distances, scratch);
  for (VertexId k = 1; k < kSides / 2; ++k) {
    EXPECT_NEAR(distances[kFirstRing + k], distances[kFirstRing + kSides - k], 1e-6) << "ring vertex " << k;
  }
}

// No path on the surface is shorter than the straight line through space: a
// triangle update whose line from the virtual source misses edge XY must not
// be taken as a shortcut.
TEST(Geodesics, NoDistanceIsShorterThanTheStraightLine) {
  for (const char* name : {"torus.off", "atrium.off"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh mesh = testing::committed(name);
    const auto solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
    SolverScratch scratch;
    std::vector<double> distances(mesh.vertex_count());
    for (VertexId source = 0; source < mesh.vertex_count(); source += 97) {
      solver->solve(source, distances, scratch);
      for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const double straight = distance(mesh.positions()[v], mesh.positions()[source]);
        ASSERT_GE(distances[v], straight * (1 - 1e-6)) << "from " << source << " to " << v;
      }
    }
  }
}

TEST(Geodesics, ResultDoesNotDependOnThreadCount) {
  const SurfaceMesh patch = testing::committed("patch.off");
  const DistanceTable one = compute_all_pairs(patch, GeodesicMethod::fast_marching, 1, true);
  const DistanceTable two = compute_all_pairs(patch, GeodesicMethod::fast_marching, 2, true);
  EXPECT_TRUE(std::equal(one.values().begin(), one.values().end(), two.values().begin()));
}

// The triangle stencils are made piece by piece of triangles on any number
// of threads: the same records in the same order as on one.
TEST(Geodesics, TriangleStencilsDoNotDependOnThreadCount) {
  const SurfaceMesh atrium = generate_mesh_at("atrium", 40000);  // 80,000 triangles: 5 pieces
  const TriangleStencils one = build_triangle_stencils(atrium, 1);
  ASSERT_GT(one.virtual_updates.size(), 1000u);  // obtuse corners in every piece
  const auto same_bytes = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
  };
  for (const unsigned threads : {2u, 7u}) {
    const TriangleStencils many = build_triangle_stencils(atrium, threads);
    EXPECT_EQ(many.triangle_offsets, one.triangle_offsets);
    EXPECT_EQ(many.virtual_offsets, one.virtual_offsets);
    EXPECT_TRUE(same_bytes(many.triangles, one.triangles)) << threads << " threads";
    EXPECT_TRUE(same_bytes(many.virtual_updates, one.virtual_updates)) << threads << " threads";
  }
}

// A stopped solve is the full solve inside the radius, bit for bit (the same
// vertices accepted in the same order), and +inf beyond it.
TEST(GeodesicSolver, AStoppedSolveEqualsTheFullOneInsideTheRadius) {
  const SurfaceMesh torus = testing::committed("torus.off");
  for (const GeodesicMethod method :
       {GeodesicMethod::fast_marching, GeodesicMethod::dijkstra, GeodesicMethod::fast_iterative}) {
    SCOPED_TRACE(method_name(method));
    const auto solver = make_geodesic_solver(torus, method);
    SolverScratch scratch;
    std::vector<double> full(torus.vertex_count()), stopped(torus.vertex_count());
    for (const VertexId source : {VertexId(0), VertexId(777)}) {
      solver->solve(source, full, scratch);
      const double radius = 0.6;  // about a fifth of the way round the tube's long circle
      solver->solve(source, stopped, scratch, radius);
      std::size_t inside = 0;
      for (std::size_t v = 0; v < full.size(); ++v) {
        if (full[v] <= radius) {
          ++inside;
          ASSERT_EQ(stopped[v], full[v]) << "vertex " << v;
        } else {
          ASSERT_TRUE(std::isinf(stopped[v])) << "vertex " << v << " beyond the radius has " << stopped[v];
        }
      }
      EXPECT_GT(inside, 50u);
      EXPECT_LT(inside, full.size() / 2);
    }
  }
}

// A ball solve touches only its ball, gives exactly the full solve's values
// inside the radius, and leaves the scratch clean: interleaved with full
// solves on the same scratch, every answer is as if computed alone.
TEST(GeodesicSolver, BallsAreTheFullSolveInsideTheRadius) {
  const SurfaceMesh sphere = testing::committed("sphere.off");
  for (const GeodesicMethod method :
       {GeodesicMethod::fast_marching, GeodesicMethod::dijkstra, GeodesicMethod::fast_iterative}) {
    SCOPED_TRACE(method_name(method));
    const auto solver = make_geodesic_solver(sphere, method);
    SolverScratch scratch;
    std::vector<double> full(sphere.vertex_count());
    for (const VertexId source : {VertexId(0), VertexId(1234), VertexId(3999), VertexId(1234)}) {
      const double radius = 0.3;
      const Ball ball = solver->solve_ball(source, radius, scratch);
      solver->solve(source, full, scratch);
      ASSERT_TRUE(std::is_sorted(ball.vertices.begin(), ball.vertices.end()));
      std::size_t k = 0;
      for (std::size_t v = 0; v < full.size(); ++v) {
        if (full[v] > radius) continue;
        ASSERT_LT(k, ball.vertices.size());
        ASSERT_EQ(ball.vertices[k], v);
        ASSERT_EQ(ball.distances[k], float(full[v])) << "vertex " << v;
        ++k;
      }
      EXPECT_EQ(k, ball.vertices.size()) << "the ball has vertices beyond its radius";
      EXPECT_GT(k, 50u);
      EXPECT_TRUE(std::all_of(scratch.accepted.begin(), scratch.accepted.end(), [](auto a) { return a == 0; }));
      EXPECT_TRUE(std::all_of(scratch.distances.begin(), scratch.distances.end(), [](double d) { return std::isinf(d); }));
    }
  }
}

// A march from a point inside a triangle starts from its corners' fans
// (geodesics/point_seeds): on the flat patch every vertex is then at its
// straight line from the point to a few hundredths of an edge (0.032
// measured, what a march from a vertex leaves too). From the
// corners alone, a fan vertex whose update needs a farther one was
// accepted first, through the corner, up to a third of an edge too far
// (0.30), and the march carried that outward.
TEST(GeodesicSolver, AMarchFromAPointStartsFromItsCornersFans) {
  const SurfaceMesh patch = testing::committed("patch.off");
  const auto solver = make_geodesic_solver(patch, GeodesicMethod::fast_marching);
  const VertexTriangles rings = vertex_triangles(patch.triangles(), patch.vertex_count());
  const auto& p = patch.positions();
  SolverScratch scratch;
  PointSeeds seeds;
  std::vector<std::pair<VertexId, float>> within;
  SplitMix64 random(5);
  double worst_from_fans = 0, worst_from_corners = 0;
  for (int source = 0; source < 200; ++source) {
    const auto triangle = std::uint32_t(random.below(patch.triangles().size()));
    const Triangle& t = patch.triangles()[triangle];
    const double a = random.uniform(), b = random.uniform() * (1 - a);
    const SurfaceLocation at{triangle, {1 - a - b, a, b}, (1 - a - b) * p[t[0]] + a * p[t[1]] + b * p[t[2]]};
    const auto worst_error = [&] {
      double worst = 0;
      for (const auto& [v, d] : within) worst = std::max(worst, std::abs(d - distance(at.at, p[v])));
      return worst / patch.mean_edge_length();
    };
    point_seeds(patch, rings, at, seeds);
    solver->solve_ball_from(seeds.vertices, seeds.distances, INFINITY, scratch, within);
    worst_from_fans = std::max(worst_from_fans, worst_error());
    const double starts[3] = {distance(at.at, p[t[0]]), distance(at.at, p[t[1]]), distance(at.at, p[t[2]])};
    solver->solve_ball_from(t, starts, INFINITY, scratch, within);
    worst_from_corners = std::max(worst_from_corners, worst_error());
  }
  std::printf("a march from a point, worst error in edges: from the corners' fans %.4f, from the corners %.4f\n",
              worst_from_fans, worst_from_corners);
  EXPECT_LT(worst_from_fans, 0.05);
  EXPECT_GT(worst_from_corners, 4 * worst_from_fans);  // what the fans are for
}

// A point inside a triangle, read from a march's distances to its corners:
// on the flat patch the march from a point is the straight line at the
// vertices, and so is the point's distance from the source those three
// distances lay in the triangle's plane (geodesics/planar_source), where
// through a corner alone it reads a good part of an edge too far.
TEST(GeodesicSolver, APointInsideATriangleIsReadFromASourceInItsPlane) {
  const SurfaceMesh patch = testing::committed("patch.off");
  const auto solver = make_geodesic_solver(patch, GeodesicMethod::fast_marching);
  const VertexTriangles rings = vertex_triangles(patch.triangles(), patch.vertex_count());
  const auto& p = patch.positions();
  const auto& triangles = patch.triangles();
  SolverScratch scratch;
  PointSeeds seeds;
  std::vector<std::pair<VertexId, float>> within;
  std::vector<double> marched(patch.vertex_count());
  SplitMix64 random(11);
  double in_plane = 0, through_corners = 0;
  int pairs = 0;
  auto inside = [&](const Triangle& t) {
    const double a = random.uniform(), b = random.uniform() * (1 - a);
    return (1 - a - b) * p[t[0]] + a * p[t[1]] + b * p[t[2]];
  };
  for (int source = 0; source < 20; ++source) {
    const auto from_index = std::uint32_t(random.below(triangles.size()));
    const Vec3 q = inside(triangles[from_index]);
    point_seeds(patch, rings, {from_index, {}, q}, seeds);
    solver->solve_ball_from(seeds.vertices, seeds.distances, INFINITY, scratch, within);
    for (const auto& [v, d] : within) marched[v] = d;
    for (int target = 0; target < 50; ++target) {
      const auto to_index = std::uint32_t(random.below(triangles.size()));
      const Triangle& to = triangles[to_index];
      const Vec3 at = inside(to);
      const double exact = distance(q, at);
      if (exact < 3 * patch.mean_edge_length()) continue;
      const std::array<double, 3> corner_distance{marched[to[0]], marched[to[1]], marched[to[2]]};
      const plane_frame frame = triangle_frame(patch, to_index);
      const planar_source laid = planar_source_of(frame, corner_distance[0], corner_distance[1], corner_distance[2]);
      const double x = frame_x(frame, to_vec3d(at)), y = frame_y(frame, to_vec3d(at));
      in_plane += std::abs(planar_source_distance(frame, laid, x, y) - exact);
      double corner = INFINITY;
      for (int c = 0; c < 3; ++c) corner = std::min(corner, corner_distance[c] + distance(p[to[c]], at));
      through_corners += corner - exact;
      ++pairs;
    }
  }
  ASSERT_GT(pairs, 500);
  in_plane /= pairs * patch.mean_edge_length();
  through_corners /= pairs * patch.mean_edge_length();
  std::printf("a point in a triangle, mean error in edges: from the source in its plane %.4f, through a corner %.4f\n",
              in_plane, through_corners);
  EXPECT_LT(in_plane, 0.02);
  EXPECT_LT(in_plane, through_corners / 5);
}

// Where a triangle's three distances fit no source (a sliver, across whose
// height they differ faster than any distance can: turbine at 1,024, a
// ball's corner a twelfth too far), each corner still reads its own
// distance, and a point inside no nearer or farther than the corners allow.
// The source placed without that bound read the corner beside the far one
// a tenth of a spacing too near.
TEST(GeodesicSolver, ATriangleWhoseDistancesFitNoSourceReadsItsCornersAtTheirOwn) {
  // turbine's sliver: edges 0.2881, 0.1574 and 0.1317 spacings.
  const double base = 0.2881, to_third = 0.1317, from_second = 0.1574;
  const double x = (base * base + to_third * to_third - from_second * from_second) / (2 * base);
  const SurfaceMesh sliver({{0, 0, 0}, {base, 0, 0}, {x, std::sqrt(to_third * to_third - x * x), 0}}, {{0, 1, 2}});
  const plane_frame frame = triangle_frame(sliver, 0);
  const std::array<double, 3> corner_distance{0.7338, 0.5298, 0.6852};
  const planar_source source = planar_source_of(frame, corner_distance[0], corner_distance[1], corner_distance[2]);
  const auto& p = sliver.positions();
  for (int c = 0; c < 3; ++c) {
    const double cx = frame_x(frame, to_vec3d(p[c])), cy = frame_y(frame, to_vec3d(p[c]));
    EXPECT_NEAR(planar_source_distance(frame, source, cx, cy), corner_distance[c], 1e-12) << "corner " << c;
  }
  const Vec3 middle = (1.0 / 3) * (p[0] + p[1] + p[2]);
  const double mx = frame_x(frame, to_vec3d(middle)), my = frame_y(frame, to_vec3d(middle));
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(planar_source_distance(frame, source, mx, my), corner_distance[c] - distance(middle, p[c]) - 1e-12);
    EXPECT_LE(planar_source_distance(frame, source, mx, my), corner_distance[c] + distance(middle, p[c]) + 1e-12);
  }
}

// Several sources: each vertex gets the distance to its nearest source. On
// the edge graph that is exactly the smallest single-source distance. Fast
// marching's fronts meet between the sources, where a vertex may be reached
// first by another stencil than in its own source's solve: it agrees to a
// few hundredths of an edge (0.024 measured; combining two sources' values
// in one triangle update, before origins were tracked, gave 0.27).
TEST(GeodesicSolver, SeveralSourcesGiveTheDistanceToTheNearest) {
  const SurfaceMesh sphere = testing::committed("sphere.off");
  const std::vector<VertexId> sources = {3, 1500, 2900};
  for (const GeodesicMethod method :
       {GeodesicMethod::dijkstra, GeodesicMethod::fast_marching, GeodesicMethod::fast_iterative}) {
    SCOPED_TRACE(method_name(method));
    const auto solver = make_geodesic_solver(sphere, method);
    SolverScratch scratch;
    std::vector<double> nearest(sphere.vertex_count(), INFINITY), single(sphere.vertex_count());
    for (const VertexId source : sources) {
      solver->solve(source, single, scratch);
      for (std::size_t v = 0; v < single.size(); ++v) nearest[v] = std::min(nearest[v], single[v]);
    }
    std::vector<double> together(sphere.vertex_count());
    solver->solve(sources, together, scratch);
    double worst = 0;
    for (std::size_t v = 0; v < together.size(); ++v) worst = std::max(worst, std::abs(together[v] - nearest[v]));
    for (const VertexId source : sources) EXPECT_EQ(together[source], 0.0);
    if (method == GeodesicMethod::dijkstra) {
      EXPECT_EQ(worst, 0.0);
    } else {
      std::printf("%s from 3 sources: largest difference from the nearest single solve %.2e (%.3f edges)\n",
                  method_name(method).c_str(), worst, worst / sphere.mean_edge_length());
      EXPECT_LT(worst, 0.1 * sphere.mean_edge_length());
    }
  }
}

// The fast iterative method converges to fast marching's distances: the
// same stencils and update, only their order differs (docs/GEODESICS.md).
TEST(GeodesicSolver, TheFastIterativeMethodReachesFastMarchingsDistances) {
  for (const char* name : {"sphere.off", "torus.off", "atrium.off", "patch.off"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh mesh = testing::committed(name);
    const auto fmm = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
    const auto fim = make_geodesic_solver(mesh, GeodesicMethod::fast_iterative);
    SolverScratch scratch;
    std::vector<double> marched(mesh.vertex_count()), iterated(mesh.vertex_count());
    double sum = 0, worst = 0;
    std::size_t count = 0;
    for (VertexId source = 0; source < mesh.vertex_count(); source += VertexId(mesh.vertex_count() / 5 + 1)) {
      fmm->solve(source, marched, scratch);
      fim->solve(source, iterated, scratch);
      for (std::size_t v = 0; v < marched.size(); ++v) {
        ASSERT_EQ(std::isinf(marched[v]), std::isinf(iterated[v])) << "vertex " << v;
        if (std::isinf(marched[v]) || marched[v] < 3 * mesh.mean_edge_length()) continue;
        const double relative = std::abs(iterated[v] - marched[v]) / marched[v];
        sum += relative;
        worst = std::max(worst, relative);
        ++count;
      }
    }
    std::printf("%s: fim against fmm, relative difference %.2e mean, %.2e largest\n", name, sum / double(count), worst);
    EXPECT_LT(sum / double(count), 1e-4);
    EXPECT_LT(worst, 0.02);
  }
}

// The fast iterative method ends at a fixed point: from the distances it
// returns, no update it makes (edges, triangles, virtual triangles) lowers
// any vertex by more than the share it ignores (kLeastDrop, 1e-7). Taken
// nearest first, a vertex lowered after it was taken must be taken again:
// rare on the committed meshes (the torus), common on CGAL's cheese, whose
// slivers make updates that are not monotone.
TEST(GeodesicSolver, TheFastIterativeMethodEndsWhereNoUpdateLowersAVertex) {
  std::vector<std::pair<std::string, SurfaceMesh>> meshes;
  for (const char* name : {"sphere.off", "torus.off", "atrium.off", "patch.off", "high_valence.off"}) {
    meshes.emplace_back(name, testing::committed(name));
  }
  if (auto cheese = testing::cgal_mesh("cheese.off")) meshes.emplace_back("cheese.off", std::move(*cheese));
  for (const auto& [name, mesh] : meshes) {
    SCOPED_TRACE(name);
    const FastIterativeMethod fim(mesh);
    const TriangleStencils& stencils = fim.stencils();
    SolverScratch scratch;
    std::vector<double> d(mesh.vertex_count());
    std::size_t violations = 0;
    double worst = 0;
    const auto check = [&](VertexId target, double candidate) {
      if (std::isinf(d[target]) || !(candidate < d[target] * (1 - 2e-7))) return;
      ++violations;
      worst = std::max(worst, 1 - candidate / d[target]);
    };
    for (VertexId source = 0; source < mesh.vertex_count(); source += VertexId(mesh.vertex_count() / 7 + 1)) {
      fim.solve(source, d, scratch);
      for (VertexId x = 0; x < mesh.vertex_count(); ++x) {
        if (std::isinf(d[x])) continue;
        for (std::uint32_t k = mesh.ring_offsets()[x]; k < mesh.ring_offsets()[x + 1]; ++k) {
          check(mesh.ring_neighbors()[k], d[x] + fim.edge_lengths()[k]);
        }
        for (std::uint32_t k = stencils.triangle_offsets[x]; k < stencils.triangle_offsets[x + 1]; ++k) {
          const TriangleAtVertex& t = stencils.triangles[k];
          if (!std::isinf(d[t.a])) check(t.b, point_source_update(t.b_from_a, d[x], d[t.a]));
          if (!std::isinf(d[t.b])) check(t.a, point_source_update(t.a_from_b, d[x], d[t.b]));
        }
        for (std::uint32_t k = stencils.virtual_offsets[x]; k < stencils.virtual_offsets[x + 1]; ++k) {
          const VirtualUpdate& u = stencils.virtual_updates[k];
          if (!std::isinf(d[u.other])) check(u.target, point_source_update(u.frame, d[x], d[u.other]));
        }
      }
    }
    EXPECT_EQ(violations, 0u) << "the largest drop left " << worst;
  }
}

TEST(MemoryGuard, RefusesATableThatDoesNotFitAndSaysWhatWould) {
  EXPECT_NO_THROW(check_table_fits(1000, 4, 1ull << 30, "distance table", "host memory"));
  try {
    check_table_fits(100000, 4, 1ull << 30, "distance table", "host memory");
    FAIL() << "a 37 GiB table was accepted with 1 GiB available";
  } catch (const UserError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the 100000 x 100000 distance table needs 37.25 GiB but host memory holds 1.00 GiB"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("at most 16384 vertices fit"), std::string::npos) << message;  // sqrt(2^30 / 4)
  }
  EXPECT_EQ(max_vertices_for(400), 10u);
  EXPECT_EQ(max_vertices_for(600, 6), 10u);
}

}  // namespace
}  // namespace meshparticles
