#include "mesh/surface_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "mesh/io/mesh_reader.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/mesh_topology.hpp"

namespace meshparticles {
namespace {

SurfaceMesh read_committed(const std::string& name) {
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_mesh(std::string(MESHES_DIR) + "/" + name, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return mesh;
}

TEST(SurfaceMesh, TetrahedronAdjacencyIsSortedAndComplete) {
  const SurfaceMesh mesh = generate_mesh("tetrahedron");
  ASSERT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.edge_count(), 6u);
  for (VertexId v = 0; v < 4; ++v) {
    EXPECT_EQ(mesh.valence(v), 3u);
    const auto ring = mesh.one_ring(v);
    EXPECT_TRUE(std::is_sorted(ring.begin(), ring.end()));
    EXPECT_EQ(std::count(ring.begin(), ring.end(), v), 0);
  }
  EXPECT_EQ(mesh.component_count(), 1u);
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
  // Regular tetrahedron with edge 2*sqrt(2): area 4 * sqrt(3)/4 * 8.
  EXPECT_NEAR(mesh.area(), 8 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(mesh.mean_edge_length(), 2 * std::sqrt(2.0), 1e-12);
}

TEST(SurfaceMesh, TwoPiecesAreTwoComponents) {
  const SurfaceMesh mesh = generate_mesh("two_pieces");
  EXPECT_EQ(mesh.component_count(), 2u);
  EXPECT_EQ(mesh.component_of(0), 0u);
  EXPECT_EQ(mesh.component_of(7), 1u);
}

// Every vertex is a point of the surface: one outside every triangle is
// refused (the readers drop such vertices before building the mesh).
TEST(SurfaceMesh, RefusesAVertexInNoTriangle) {
  const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  EXPECT_THROW(SurfaceMesh(positions, {{0, 1, 2}}), std::invalid_argument);
  EXPECT_NO_THROW(SurfaceMesh({positions.begin(), positions.begin() + 3}, {{0, 1, 2}}));
}

TEST(SurfaceMesh, HighValenceApexHasNoCap) {
  const SurfaceMesh mesh = generate_mesh("high_valence");
  EXPECT_EQ(mesh.valence(0), 24u);
  EXPECT_EQ(mesh.max_valence(), 24u);
}

TEST(CommittedMeshes, SphereIsTheUnitSphereWithIrregularValence) {
  const SurfaceMesh mesh = read_committed("sphere.off");
  EXPECT_NEAR(double(mesh.vertex_count()), 4000, 100);
  EXPECT_NEAR(mesh.area(), 4 * std::numbers::pi, 0.01 * 4 * std::numbers::pi);
  EXPECT_EQ(mesh.component_count(), 1u);
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
  std::size_t min_valence = 100;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) min_valence = std::min(min_valence, mesh.valence(v));
  EXPECT_LE(min_valence, 5u);
  EXPECT_GE(mesh.max_valence(), 7u);
}

TEST(CommittedMeshes, TorusAndAtriumHaveTheirSizesAndTopology) {
  const SurfaceMesh torus = read_committed("torus.off");
  EXPECT_NEAR(double(torus.vertex_count()), 1500, 50);
  // Torus R = 1, r = 0.4: area 4 pi^2 R r; Euler characteristic 0.
  EXPECT_NEAR(torus.area(), 4 * std::numbers::pi * std::numbers::pi * 0.4, 0.02 * 15.8);
  EXPECT_EQ(long(torus.vertex_count()) - long(torus.edge_count()) + long(torus.triangle_count()), 0);
  const SurfaceMesh atrium = read_committed("atrium.off");
  EXPECT_NEAR(double(atrium.vertex_count()), 10500, 200);
  EXPECT_EQ(long(atrium.vertex_count()) - long(atrium.edge_count()) + long(atrium.triangle_count()), 2);
}

TEST(CommittedMeshes, PatchIsOpenAndFlat) {
  const SurfaceMesh patch = read_committed("patch.off");
  EXPECT_GT(patch.boundary_vertex_count(), 0u);
  EXPECT_NEAR(patch.area(), 1.0, 1e-9);
}

TEST(MeshTopology, CommittedMeshesHaveTheirComponentsLoopsAndGenus) {
  const MeshTopology sphere = mesh_topology(read_committed("sphere.off"));
  EXPECT_EQ(sphere, (MeshTopology{1, 0, 2, 0}));
  EXPECT_EQ(describe(sphere), "1 component, genus 0, no boundary");
  EXPECT_EQ(mesh_topology(read_committed("torus.off")), (MeshTopology{1, 0, 0, 1}));
  const MeshTopology patch = mesh_topology(read_committed("patch.off"));
  EXPECT_EQ(patch, (MeshTopology{1, 1, 1, 0}));
  EXPECT_EQ(describe(patch), "1 component, genus 0, 1 boundary loop");
  EXPECT_EQ(mesh_topology(generate_mesh("two_pieces")).components, 2u);
}

TEST(MeshTopology, AnOpenTubeHasTwoBoundaryLoops) {
  // Eight quads round a cylinder, each as two triangles: two rims, genus 0.
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (VertexId k = 0; k < 8; ++k) {
    const double angle = 2 * std::numbers::pi * k / 8;
    positions.push_back({std::cos(angle), std::sin(angle), 0});
    positions.push_back({std::cos(angle), std::sin(angle), 1});
  }
  for (VertexId k = 0; k < 8; ++k) {
    const VertexId a = 2 * k, b = 2 * ((k + 1) % 8);
    triangles.push_back({a, b, VertexId(b + 1)});
    triangles.push_back({a, VertexId(b + 1), VertexId(a + 1)});
  }
  const MeshTopology tube = mesh_topology(SurfaceMesh(positions, triangles));
  EXPECT_EQ(tube, (MeshTopology{1, 2, 0, 0}));
  EXPECT_EQ(describe(tube), "1 component, genus 0, 2 boundary loops");
}

// Regeneration, byte for byte: tests/command_outputs.sh.

}  // namespace
}  // namespace meshparticles
