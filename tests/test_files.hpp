#pragma once
// Files the tests read, shared so that each test file need not define its own
// (and so that the test sources compile together: tests/CMakeLists.txt).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
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

// Every mesh of meshes/, for tests over them all (::testing::ValuesIn).
inline constexpr const char* kCommittedMeshes[] = {"sphere.off",       "atrium.off",     "torus.off",      "patch.off",
                                                   "high_valence.off", "two_pieces.off", "tetrahedron.off"};

// A test over committed meshes named by each mesh's stem ("atrium").
inline std::string stem(const ::testing::TestParamInfo<const char*>& mesh) {
  return std::string(mesh.param).substr(0, std::string(mesh.param).find('.'));
}

// CGAL's meshes (Debian's libcgal-demo): a real scan's irregular triangles,
// not a generator's. scripts/test.sh unpacks them (scripts/cgal_meshes.sh)
// and names the folder in $MESHPARTICLES_CGAL_MESHES; without it, where
// that script puts them. A mesh not there fails the test, saying how to get
// it: a test that skipped would pass CI without ever running.
inline std::optional<SurfaceMesh> cgal_mesh(const std::string& name) {
  std::filesystem::path folder;
  if (const char* given = std::getenv("MESHPARTICLES_CGAL_MESHES")) {
    folder = given;
  } else {
    const char* cache = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    folder = (cache && *cache ? std::filesystem::path(cache) : std::filesystem::path(home ? home : "") / ".cache") /
             "meshparticles" / "cgal-data" / "data" / "meshes";
  }
  const std::filesystem::path path = folder / name;
  if (!std::filesystem::exists(path)) {
    ADD_FAILURE() << path << " is not here: scripts/cgal_meshes.sh installs and unpacks CGAL's meshes "
                  << "(or set $MESHPARTICLES_CGAL_MESHES)";
    return std::nullopt;
  }
  std::vector<std::string> warnings;
  return read_mesh(path.string(), warnings);
}

}  // namespace meshparticles::testing
