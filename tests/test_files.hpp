#pragma once
// Files the tests read, shared so that each test file need not define its own
// (and so that the test sources compile together: tests/CMakeLists.txt).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mesh/io/mesh_reader.hpp"

namespace meshparticles::testing {

// A file's bytes, as they are on disk.
inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// A mesh of meshes/ by its file name.
inline SurfaceMesh committed(const std::string& name) {
  std::vector<std::string> warnings;
  return read_mesh(std::string(MESHES_DIR) + "/" + name, warnings);
}

// A file of tests/data by its name.
inline std::string test_data_file(const std::string& name) { return std::string(TEST_DATA_DIR) + "/" + name; }

// A test over committed meshes named by each mesh's stem ("atrium").
inline std::string stem(const ::testing::TestParamInfo<const char*>& mesh) {
  return std::string(mesh.param).substr(0, std::string(mesh.param).find('.'));
}

}  // namespace meshparticles::testing
