// What the checks keep, drop and refuse in non-manifold input: by default
// one warning line per kind, with MeshReadOptions::strict the refusals of
// old. And a mesh with no area, refused whatever the options.
#include "mesh/mesh_checks.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "common/user_error.hpp"
#include "mesh/coincident_sheets.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "test_files.hpp"

namespace meshparticles {
namespace {


std::string strict_refusal(const std::filesystem::path& file) {
  std::vector<std::string> warnings;
  try {
    read_mesh(file, warnings, {.strict = true});
  } catch (const UserError& error) {
    return error.what();
  }
  return "accepted";
}

TEST(MeshChecks, TwoFansAtAVertexAreKeptWithOneWarning) {
  // Two tetrahedra touching at vertex 0.
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("nonmanifold_vertex.off"), warnings);
  EXPECT_EQ(mesh.vertex_count(), 7u);
  EXPECT_EQ(mesh.triangle_count(), 8u);
  EXPECT_EQ(mesh.component_count(), 1u);
  EXPECT_EQ(mesh.valence(0), 6u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], testing::test_data_file("nonmanifold_vertex.off") +
                             ": 1 non-manifold vertex (e.g. vertex 0, where 2 fans of triangles meet) kept: a shortest "
                             "path may pass through them");
  EXPECT_EQ(strict_refusal(testing::test_data_file("nonmanifold_vertex.off")),
            testing::test_data_file("nonmanifold_vertex.off") + ": non-manifold vertex 0 (its triangles form 2 separate fans)");
}

TEST(MeshChecks, AnEdgeInThreeTrianglesJoinsThemAll) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("nonmanifold_edge.off"), warnings);
  EXPECT_EQ(mesh.triangle_count(), 3u);
  EXPECT_EQ(mesh.edge_count(), 7u);
  EXPECT_EQ(mesh.valence(0), 4u);  // 1, 2, 3 and 4
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find(": 1 non-manifold edge (e.g. 0-1, in 3 triangles) kept: each joins all its triangles"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("disagree in orientation"), std::string::npos) << warnings[1];
  EXPECT_EQ(strict_refusal(testing::test_data_file("nonmanifold_edge.off")),
            testing::test_data_file("nonmanifold_edge.off") + ": non-manifold edge 0-1 is shared by more than two faces");
}

PolygonSoup tetrahedron_with_repeats() {
  PolygonSoup soup;
  soup.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (const auto& [a, b, c] : {std::array{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {2, 1, 0}, {3, 1, 0}}) {
    soup.add_triangle(a, b, c);
  }
  return soup;
}

TEST(MeshChecks, RepeatedTrianglesAreDroppedWithOneWarning) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = build_checked_mesh(tetrahedron_with_repeats(), "tetra", warnings);
  EXPECT_EQ(mesh.triangle_count(), 4u);
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
  EXPECT_NEAR(mesh.area(), 8 * std::sqrt(3.0), 1e-12);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "tetra: 2 repeated triangles (same three vertices as an earlier one) dropped");
  try {
    build_checked_mesh(tetrahedron_with_repeats(), "tetra", warnings, {.strict = true});
    ADD_FAILURE() << "strict accepted a repeated triangle";
  } catch (const UserError& error) {
    EXPECT_EQ(std::string(error.what()), "tetra: triangle 4 repeats triangle 0 (same three vertices)");
  }
}

TEST(MeshChecks, StrictAcceptsManifoldMeshesUnchanged) {
  for (const char* name : {"tetrahedron.ply", "off_dialect.off", "octahedron_tristrips.ply"}) {
    EXPECT_EQ(strict_refusal(testing::test_data_file(name)), "accepted") << name;
  }
}

TEST(MeshChecks, ManyPinchedVerticesStillGiveOneLine) {
  // A strip of tetrahedra, each touching the next at one vertex.
  PolygonSoup soup;
  constexpr int kTetrahedra = 5;
  for (int t = 0; t < kTetrahedra; ++t) {
    const double x = 2.0 * t;
    const auto first = static_cast<long long>(soup.vertices.size()) - (t > 0 ? 1 : 0);  // shares the last apex
    if (t == 0) soup.vertices.push_back({x, 0, 0});
    soup.vertices.insert(soup.vertices.end(), {{x + 1, 1, 0}, {x + 1, -1, 0}, {x + 2, 0, 0}});
    const long long a = first, b = first + 1, c = first + 2, d = first + 3;
    soup.add_triangle(a, b, c);
    soup.add_triangle(a, c, d);
    soup.add_triangle(a, d, b);
    soup.add_triangle(b, d, c);
  }
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = build_checked_mesh(soup, "chain", warnings);
  EXPECT_EQ(mesh.component_count(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("chain: " + std::to_string(kTetrahedra - 1) + " non-manifold vertices (e.g. vertex 3,"),
            std::string::npos)
      << warnings[0];
}

// Issue 29: a mesh with no area has no surface for particles; `run` used to
// answer "--sigma 0 is too small to compute with" though no --sigma was given.
TEST(MeshChecks, AMeshWithNoAreaIsRefusedInOneLine) {
  for (const char* name : {"no_area.off", "no_area_collinear.off"}) {
    const std::string expected =
        testing::test_data_file(name) + ": the mesh has no area: every triangle is degenerate (its corners at one point or on one line)";
    std::vector<std::string> warnings;
    try {
      read_mesh(testing::test_data_file(name), warnings);
      ADD_FAILURE() << name << " was accepted";
    } catch (const UserError& error) {
      EXPECT_EQ(std::string(error.what()), expected);
      EXPECT_EQ(error.exit_code(), 2);
    }
    EXPECT_EQ(strict_refusal(testing::test_data_file(name)), expected);
  }
}

PolygonSoup scaled_tetrahedron(double scale) {
  PolygonSoup soup;
  for (const Vec3& p : std::vector<Vec3>{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}) {
    soup.vertices.push_back({p.x * scale, p.y * scale, p.z * scale});
  }
  for (const auto& [a, b, c] : {std::array{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}) soup.add_triangle(a, b, c);
  return soup;
}

TEST(MeshChecks, AnAreaThatOverflowsIsRefused) {
  std::vector<std::string> warnings;
  try {
    build_checked_mesh(scaled_tetrahedron(1e200), "huge", warnings);
    ADD_FAILURE() << "an area of about 1e400 was accepted";
  } catch (const UserError& error) {
    EXPECT_EQ(std::string(error.what()),
              "huge: the mesh's area is not a finite number (coordinates too large to compute with)");
  }
}

TEST(MeshChecks, SmallAndLargeMeshesKeepTheirArea) {
  // Micrometres, far below and far above: "no area" is relative to each
  // triangle's own edges, never to an absolute size.
  for (const double scale : {1e-6, 1e-60, 1e60}) {
    std::vector<std::string> warnings;
    const SurfaceMesh mesh = build_checked_mesh(scaled_tetrahedron(scale), "small", warnings);
    EXPECT_NEAR(mesh.area() / (scale * scale), 8 * std::sqrt(3.0), 1e-12) << scale;
    EXPECT_TRUE(warnings.empty()) << scale << ": " << warnings.front();
  }
  // One triangle with area among degenerate ones is enough: kept, one warning.
  PolygonSoup soup;
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(3, 4, 5);
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = build_checked_mesh(soup, "one", warnings);
  EXPECT_DOUBLE_EQ(mesh.area(), 0.5);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "one: 1 degenerate (zero-area) triangle");
}

// Two sheets at one place through other vertices (a square and its flipped
// copy): a particle file cannot say which sheet a point is on, so the check
// names them once; one square alone gives no warning.
TEST(MeshChecks, CoincidentSheetsAreNamedInOneWarning) {
  PolygonSoup soup;
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(0, 2, 3);
  std::vector<std::string> warnings;
  const SurfaceMesh one = build_checked_mesh(soup, "square", warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(coincident_sheets(one).triangles, 0u);
  soup.vertices.insert(soup.vertices.end(), {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  soup.add_triangle(4, 6, 5);
  soup.add_triangle(4, 7, 6);
  const SurfaceMesh two = build_checked_mesh(soup, "squares", warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("squares: 4 triangles lie on other triangles (coincident sheets, e.g. at 0.666667 "
                              "0.333333 0): a point there is on each sheet, so a particle file cannot say which",
                              0),
            0u)
      << warnings[0];
  EXPECT_EQ(coincident_sheets(two).triangles, 4u);
  // Apart by the smallest step: other places, no warning.
  soup.vertices[6].z = std::nextafter(0.0, 1.0);
  warnings.clear();
  build_checked_mesh(soup, "apart", warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

}  // namespace
}  // namespace meshparticles
