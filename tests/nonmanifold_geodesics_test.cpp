// Fast marching on the two non-manifold cases the reader now keeps, against
// distances worked out by hand: two cones touching at their apexes (every
// path between them passes through the pinch vertex) and three fins sharing
// one edge (a path crosses from any fin to any other).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geodesics/fast_marching.hpp"
#include "mesh/mesh_checks.hpp"

namespace meshparticles {
namespace {

std::vector<double> distances_from(const SurfaceMesh& mesh, VertexId source) {
  std::vector<double> distances(mesh.vertex_count());
  SolverScratch scratch;
  FastMarching(mesh).solve(source, distances, scratch);
  return distances;
}

SurfaceMesh checked(const PolygonSoup& soup, std::vector<std::string>& warnings) {
  return build_checked_mesh(soup, "test mesh", warnings);
}

// Two cones with a common apex (vertex 0), one opening up and one down, each
// a fan of `sectors` triangles out to ring 1 and a band out to ring 2 (twice
// as far along each generator). Ring r of cone c, vertex k: 1 + c*2*sectors + (r-1)*sectors + k.
constexpr int kSectors = 12;
constexpr double kRadius = 1.0, kHeight = 1.5;
VertexId cone_vertex(int cone, int ring, int k) {
  return VertexId(1 + cone * 2 * kSectors + (ring - 1) * kSectors + (k % kSectors));
}

PolygonSoup touching_cones() {
  PolygonSoup soup;
  soup.vertices.push_back({0, 0, 0});
  for (int cone = 0; cone < 2; ++cone) {
    const double up = cone == 0 ? 1.0 : -1.0;
    for (int ring = 1; ring <= 2; ++ring) {
      for (int k = 0; k < kSectors; ++k) {
        const double angle = 2 * std::numbers::pi * k / kSectors;
        soup.vertices.push_back(
            {ring * kRadius * std::cos(angle), ring * kRadius * std::sin(angle), up * ring * kHeight});
      }
    }
    for (int k = 0; k < kSectors; ++k) {
      soup.add_triangle(0, cone_vertex(cone, 1, k), cone_vertex(cone, 1, k + 1));
      soup.add_triangle(cone_vertex(cone, 1, k), cone_vertex(cone, 2, k), cone_vertex(cone, 2, k + 1));
      soup.add_triangle(cone_vertex(cone, 1, k), cone_vertex(cone, 2, k + 1), cone_vertex(cone, 1, k + 1));
    }
  }
  return soup;
}

TEST(NonManifoldGeodesics, PathsBetweenTouchingConesPassThroughTheApex) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = checked(touching_cones(), warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 non-manifold vertex (e.g. vertex 0, where 2 fans"), std::string::npos) << warnings[0];
  EXPECT_EQ(mesh.component_count(), 1u);

  // Along a generator a cone is straight: ring r lies r * slant from the apex.
  const double slant = std::hypot(kRadius, kHeight);
  double worst = 0;
  for (const int source_ring : {1, 2}) {
    const VertexId source = cone_vertex(0, source_ring, 0);
    const std::vector<double> d = distances_from(mesh, source);
    EXPECT_NEAR(d[0], source_ring * slant, 1e-6);
    for (int ring = 1; ring <= 2; ++ring) {
      for (int k = 0; k < kSectors; ++k) {
        // On the other cone the shortest path is source -> apex -> vertex, two straight generators.
        const double exact = (source_ring + ring) * slant;
        worst = std::max(worst, std::abs(d[cone_vertex(1, ring, k)] - exact) / exact);
      }
    }
  }
  std::printf("touching cones: worst relative error across the pinch %.3g\n", worst);
  EXPECT_LE(worst, 1e-6);  // edge lengths are float32
}

// Three flat fins, each a grid of right triangles in a half-plane that
// contains the common edge from (0,0,0) to (0,0,kFinRows * kSpacing) on the z-axis.
constexpr int kFinColumns = 4, kFinRows = 8;
constexpr double kSpacing = 0.25;
VertexId fin_vertex(int fin, int column, int row) {
  // Column 0 is the shared edge, one vertex row per height.
  if (column == 0) return VertexId(row);
  return VertexId((kFinRows + 1) + fin * kFinColumns * (kFinRows + 1) + (column - 1) * (kFinRows + 1) + row);
}

PolygonSoup three_fins() {
  PolygonSoup soup;
  for (int row = 0; row <= kFinRows; ++row) soup.vertices.push_back({0, 0, row * kSpacing});
  for (int fin = 0; fin < 3; ++fin) {
    const double angle = 2 * std::numbers::pi * fin / 3;
    for (int column = 1; column <= kFinColumns; ++column) {
      for (int row = 0; row <= kFinRows; ++row) {
        const double out = column * kSpacing;
        soup.vertices.push_back({out * std::cos(angle), out * std::sin(angle), row * kSpacing});
      }
    }
    for (int column = 0; column < kFinColumns; ++column) {
      for (int row = 0; row < kFinRows; ++row) {
        const auto a = fin_vertex(fin, column, row), b = fin_vertex(fin, column + 1, row);
        const auto c = fin_vertex(fin, column + 1, row + 1), d = fin_vertex(fin, column, row + 1);
        soup.add_triangle(a, b, c);
        soup.add_triangle(a, c, d);
      }
    }
  }
  return soup;
}

TEST(NonManifoldGeodesics, PathsCrossASharedEdgeIntoEveryFin) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = checked(three_fins(), warnings);
  // Three triangles on one edge cannot all agree in orientation: that warning comes too.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find(std::to_string(kFinRows) + " non-manifold edges (e.g. 0-1, in 3 triangles) kept"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("disagree in orientation"), std::string::npos) << warnings[1];
  // A shared edge is no boundary: on the boundary are each fin's outer column
  // and the top and bottom rows, but of the shared edge only its two ends.
  EXPECT_EQ(mesh.boundary_vertex_count(), std::size_t(3 * (kFinRows + 1 + 2 * (kFinColumns - 1)) + 2));

  // Fin 0 unfolded across the shared edge lies flat against any other fin:
  // from (column u, row z) to (u', z') on another fin the path is straight
  // in that plane, |(u + u', z - z')| times the spacing.
  const int source_column = 3, source_row = 2;
  const std::vector<double> d = distances_from(mesh, fin_vertex(0, source_column, source_row));
  double worst = 0;
  for (int fin = 1; fin < 3; ++fin) {
    for (int column = 1; column <= kFinColumns; ++column) {
      for (int row = 0; row <= kFinRows; ++row) {
        const double exact = kSpacing * std::hypot(source_column + column, source_row - row);
        worst = std::max(worst, std::abs(d[fin_vertex(fin, column, row)] - exact) / exact);
      }
    }
  }
  std::printf("three fins: worst relative error across the shared edge %.3g\n", worst);
  EXPECT_LE(worst, 1e-6);
}

}  // namespace
}  // namespace meshparticles
