#include "geodesics/distance_cache.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <functional>

#include <unistd.h>

#include "fixtures/mesh_generator.hpp"

namespace meshparticles {
namespace {

class DistanceCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("meshparticles-cache-test-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory_);
    request_.cache_directory = directory_;
    request_.quiet = true;
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path directory_;
  GeodesicsRequest request_;
  const SurfaceMesh mesh_ = generate_mesh("high_valence");
};

TEST_F(DistanceCacheTest, RoundTripIsBitExactAndReused) {
  TableSource first, second;
  const DistanceTable computed = load_or_compute_distances(mesh_, request_, first);
  EXPECT_FALSE(first.from_cache);
  ASSERT_TRUE(std::filesystem::exists(first.cache_file));
  const DistanceTable loaded = load_or_compute_distances(mesh_, request_, second);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(first.cache_file, second.cache_file);
  EXPECT_EQ(0, std::memcmp(computed.values().data(), loaded.values().data(), computed.byte_size()));
  // No temporary file is left beside it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory_), {}), 1);
}

TEST_F(DistanceCacheTest, CorruptOrTruncatedFilesAreRejectedAndReplaced) {
  TableSource source;
  const DistanceTable good = load_or_compute_distances(mesh_, request_, source);
  const CacheKey key{mesh_content_hash(mesh_), std::uint32_t(mesh_.vertex_count()), request_.method};
  std::string problem;

  {  // flip one byte of the values
    std::fstream file(source.cache_file, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(100);
    file.put('\x7f');
  }
  EXPECT_FALSE(load_cached_table(source.cache_file, key, problem));
  EXPECT_NE(problem.find("corrupt"), std::string::npos) << problem;
  TableSource again;
  const DistanceTable recomputed = load_or_compute_distances(mesh_, request_, again);
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(0, std::memcmp(good.values().data(), recomputed.values().data(), good.byte_size()));
  EXPECT_TRUE(load_cached_table(source.cache_file, key, problem)) << problem;

  std::filesystem::resize_file(source.cache_file, std::filesystem::file_size(source.cache_file) - 4);
  EXPECT_FALSE(load_cached_table(source.cache_file, key, problem));
  EXPECT_NE(problem.find("truncated"), std::string::npos) << problem;
}

TEST_F(DistanceCacheTest, AnotherMeshOrSolverDoesNotMatch) {
  TableSource source;
  load_or_compute_distances(mesh_, request_, source);
  CacheKey other_mesh{mesh_content_hash(mesh_) ^ 1, std::uint32_t(mesh_.vertex_count()), request_.method};
  CacheKey other_solver{mesh_content_hash(mesh_), std::uint32_t(mesh_.vertex_count()), GeodesicMethod::dijkstra};
  std::string problem;
  EXPECT_FALSE(load_cached_table(source.cache_file, other_mesh, problem));
  EXPECT_NE(problem.find("another mesh"), std::string::npos);
  EXPECT_FALSE(load_cached_table(source.cache_file, other_solver, problem));
  EXPECT_NE(other_solver.file_in(directory_), source.cache_file);
  EXPECT_NE(mesh_content_hash(mesh_), mesh_content_hash(generate_mesh("tetrahedron")));
}

// A checksum detects damage, not who wrote the file: a table planted by
// someone else, with a valid checksum, must not be read.
TEST_F(DistanceCacheTest, TablesOthersCouldHaveWrittenAreRecomputed) {
  TableSource first;
  const DistanceTable good = load_or_compute_distances(mesh_, request_, first);
  EXPECT_EQ(std::filesystem::status(directory_).permissions() & std::filesystem::perms::all,
            std::filesystem::perms::owner_all)
      << "created 0700";
  const auto planted = [&](const std::function<void()>& plant, const std::string& expected_problem) {
    SCOPED_TRACE(expected_problem);
    std::filesystem::remove(first.cache_file);
    std::filesystem::copy_file(first.cache_file.string() + ".good", first.cache_file);
    plant();
    EXPECT_NE(cache_file_problem(first.cache_file).value_or("").find(expected_problem), std::string::npos);
    TableSource again;
    const DistanceTable table = load_or_compute_distances(mesh_, request_, again);
    EXPECT_FALSE(again.from_cache);
    EXPECT_EQ(0, std::memcmp(good.values().data(), table.values().data(), good.byte_size()));
    EXPECT_FALSE(cache_file_problem(first.cache_file)) << "replaced by our own";
  };
  std::filesystem::copy_file(first.cache_file, first.cache_file.string() + ".good");
  planted([&] { std::filesystem::permissions(first.cache_file, std::filesystem::perms::others_write,
                                             std::filesystem::perm_options::add); },
          "writable by others");
  if (::geteuid() == 0) {  // only root can give a file away
    planted([&] { ASSERT_EQ(::chown(first.cache_file.c_str(), 65534, 65534), 0); }, "owned by user 65534");
  }
  std::filesystem::remove(first.cache_file.string() + ".good");

  // A directory others can write is not used at all.
  std::filesystem::permissions(directory_, std::filesystem::perms::all);
  EXPECT_NE(cache_directory_problem(directory_).value_or("").find("can be written by others (mode 0777)"),
            std::string::npos);
  TableSource shared;
  load_or_compute_distances(mesh_, request_, shared);
  EXPECT_FALSE(shared.from_cache);
  EXPECT_TRUE(shared.cache_file.empty()) << "nothing read or written there";
}

}  // namespace
}  // namespace meshparticles
