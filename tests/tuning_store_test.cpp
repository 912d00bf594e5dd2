// The tuning file: size classes, lookups (exact, nearest, none), saving that
// keeps what was there, and files that are not tuning files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "common/user_error.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles::testing {
namespace {

class TuningStoreTest : public ::testing::Test {
 protected:
  std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("meshparticles-tuning-" + std::to_string(::getpid()));
  std::filesystem::path file = directory / "sub" / "tuning.json";
  void TearDown() override { std::filesystem::remove_all(directory); }
  void write(const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
  }
};

const std::vector<std::string> kKernels = {"naive", "tiled", "field"};

TunedSizes entry(const std::string& device, const std::string& kind, std::size_t particles, std::size_t wg,
                 std::size_t tile) {
  return {device, kind, size_class(particles), wg, tile, 1.5, "test n=" + std::to_string(particles)};
}

TEST(SizeClass, RoundsUpToAPowerOfTwo) {
  EXPECT_EQ(size_class(1), "n<=1");
  EXPECT_EQ(size_class(513), "n<=1024");
  EXPECT_EQ(size_class(1024), "n<=1024");
  EXPECT_EQ(size_class(1025), "n<=2048");
}

TEST_F(TuningStoreTest, MissingFileIsEmpty) {
  EXPECT_TRUE(TuningStore::load(file, kKernels).entries().empty());
  EXPECT_FALSE(TuningStore::load(file, kKernels).find("gpu", "tiled", 1024));
}

TEST_F(TuningStoreTest, RoundTripAndLookups) {
  TuningStore store;
  store.put(entry("gpu", "tiled", 1024, 128, 64));
  store.put(entry("gpu", "tiled", 128, 32, 16));
  store.put(entry("gpu", "naive", 1024, 16, 0));
  store.put(entry("cpu", "tiled", 1024, 8, 256));
  store.save(file);  // creates the directory

  const TuningStore loaded = TuningStore::load(file, kKernels);
  ASSERT_EQ(loaded.entries().size(), 4u);
  const auto exact = loaded.find("gpu", "tiled", 1000);
  ASSERT_TRUE(exact);
  EXPECT_EQ(exact->work_group_size, 128u);
  EXPECT_EQ(exact->tile_size, 64u);
  EXPECT_EQ(exact->measured_on, "test n=1024");
  // n<=4096 has no entry: the nearest class measured (n<=1024) answers.
  EXPECT_EQ(loaded.find("gpu", "tiled", 4000)->size_class, "n<=1024");
  EXPECT_EQ(loaded.find("gpu", "tiled", 100)->size_class, "n<=128");
  EXPECT_EQ(loaded.find("gpu", "naive", 100)->work_group_size, 16u);
  EXPECT_FALSE(loaded.find("other device", "tiled", 1024));
}

TEST_F(TuningStoreTest, PutReplacesOnlyItsOwnEntry) {
  TuningStore store;
  store.put(entry("gpu", "tiled", 1024, 128, 64));
  store.put(entry("cpu", "tiled", 1024, 8, 256));
  store.save(file);
  TuningStore again = TuningStore::load(file, kKernels);
  again.put(entry("gpu", "tiled", 1024, 256, 32));
  again.save(file);
  const TuningStore loaded = TuningStore::load(file, kKernels);
  ASSERT_EQ(loaded.entries().size(), 2u);
  EXPECT_EQ(loaded.find("gpu", "tiled", 1024)->work_group_size, 256u);
  EXPECT_EQ(loaded.find("cpu", "tiled", 1024)->tile_size, 256u);
}

TEST_F(TuningStoreTest, BadFilesNameTheFile) {
  for (const std::string text :
       {"not json", "{\"version\": 2, \"entries\": []}", "{\"version\": 1}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"tiled\", \"size_class\": \"n<=64\"}]}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"cuda\", \"size_class\": \"n<=64\", "
        "\"wg\": 8}]}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"naive\", \"size_class\": \"big\", "
        "\"wg\": 8}]}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"tiled\", \"size_class\": \"n<=64\", "
        "\"wg\": 0, \"tile\": 8}]}",
        // A fraction is not truncated, an empty or odd class is named.
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"naive\", \"size_class\": \"n<=64\", "
        "\"wg\": 32.7}]}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"naive\", \"size_class\": \"\", "
        "\"wg\": 32}]}",
        "{\"version\": 1, \"entries\": [{\"device\": \"gpu\", \"kernel\": \"naive\", \"size_class\": \"n<=48\", "
        "\"wg\": 32}]}"}) {
    SCOPED_TRACE(text);
    write(text);
    try {
      TuningStore::load(file, kKernels);
      ADD_FAILURE() << "accepted";
    } catch (const UserError& error) {
      EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    }
  }
}

TEST_F(TuningStoreTest, TwoHundredThousandEntriesLoad) {
  // put() once compared every entry with every other: 200,000 took minutes.
  // Now the whole test takes seconds. No time is asserted (busy machines and
  // sanitizer builds vary tenfold); a quadratic load shows as minutes in
  // ctest's time column.
  TuningStore store;
  for (std::size_t k = 0; k < 200000; ++k) store.put(entry("device " + std::to_string(k), "naive", 64, 8, 0));
  store.put(entry("device 7", "naive", 64, 16, 0));  // replaces, does not add
  store.save(file);
  const TuningStore loaded = TuningStore::load(file, kKernels);
  EXPECT_EQ(loaded.entries().size(), 200000u);
  EXPECT_EQ(loaded.find("device 7", "naive", 64)->work_group_size, 16u);
  EXPECT_TRUE(loaded.file_found());
  EXPECT_FALSE(TuningStore::load(directory / "absent.json", kKernels).file_found());
}

}  // namespace
}  // namespace meshparticles::testing
