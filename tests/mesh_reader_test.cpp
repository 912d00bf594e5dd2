#include "mesh/mesh_reader.hpp"

#include <gtest/gtest.h>

#include "common/user_error.hpp"

namespace meshparticles {
namespace {

std::string data(const std::string& name) { return std::string(TEST_DATA_DIR) + "/" + name; }

TEST(MeshReader, ReadsEveryFormatToTheSameTetrahedron) {
  for (const char* name : {"tetrahedron.obj", "tetrahedron.ply", "tetrahedron.stl"}) {
    std::vector<std::string> warnings;
    const SurfaceMesh mesh = read_mesh(data(name), warnings);
    EXPECT_EQ(mesh.vertex_count(), 4u) << name;
    EXPECT_EQ(mesh.triangle_count(), 4u) << name;
    EXPECT_NEAR(mesh.area(), 8 * std::sqrt(3.0), 1e-5) << name;
    EXPECT_TRUE(warnings.empty()) << name;
  }
}

TEST(MeshReader, UnreferencedVerticesAreDroppedAndInputIdsKept) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(data("unreferenced_vertices.off"), warnings);
  ASSERT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.input_id(0), 1u);
  EXPECT_EQ(mesh.input_id(1), 2u);
  EXPECT_EQ(mesh.input_id(2), 4u);
  EXPECT_EQ(mesh.input_id(3), 5u);
  EXPECT_DOUBLE_EQ(mesh.positions()[0].x, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
}

TEST(MeshReader, QuadsAreTriangulated) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(data("cube_quads.off"), warnings);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  EXPECT_NEAR(mesh.area(), 6.0, 1e-6);
  EXPECT_EQ(long(mesh.vertex_count()) - long(mesh.edge_count()) + long(mesh.triangle_count()), 2);
}

TEST(MeshReader, BrokenFilesThrowOneLineNamingTheFile) {
  for (const char* name : {"missing.off", "unknown_format.xyz", "garbage.off", "empty.off", "no_faces.off",
                           "truncated.off", "face_count_mismatch.off", "nan_coordinate.off", "nan_coordinate.ply",
                           "index_out_of_range.off", "index_out_of_range.obj", "repeated_index.off",
                           "nonmanifold_edge.off", "nonmanifold_vertex.off"}) {
    std::vector<std::string> warnings;
    try {
      read_mesh(data(name), warnings);
      ADD_FAILURE() << name << " was accepted";
    } catch (const UserError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(name), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(error.exit_code(), 2);
    }
  }
}

}  // namespace
}  // namespace meshparticles
