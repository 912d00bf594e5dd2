// Output sets replaced as a whole, temporaries of dead processes removed,
// and the files of others never touched.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/atomic_directory.hpp"
#include "common/atomic_file.hpp"
#include "common/temporary_names.hpp"
#include "common/user_error.hpp"

namespace meshparticles::testing {
namespace {

class AtomicOutputsTest : public ::testing::Test {
 protected:
  std::filesystem::path root = std::filesystem::temp_directory_path() /
                               ("meshparticles-atomic-" + std::to_string(::getpid()) + "-" +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::path out = root / "out";
  const std::set<std::string> names = {"a.txt", "b.txt"};
  void SetUp() override { std::filesystem::create_directories(root); }
  void TearDown() override { std::filesystem::remove_all(root); }

  void write_set(const std::string& text) {
    write_directory_atomically(out, names, [&](const std::filesystem::path& staging) {
      for (const auto& name : names) write_new_file(staging / name, [&](std::ostream& o) { o << text; });
    });
  }
  static std::string read(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::size_t entries_in(const std::filesystem::path& directory) const {
    return std::size_t(std::distance(std::filesystem::directory_iterator(directory), {}));
  }
};

TEST_F(AtomicOutputsTest, ReplacesTheWholeSetAndLeavesNothingBeside) {
  write_set("old");
  write_set("new");
  EXPECT_EQ(read(out / "a.txt"), "new");
  EXPECT_EQ(read(out / "b.txt"), "new");
  EXPECT_EQ(entries_in(root), 1u) << "no staging or retired directory left";
}

TEST_F(AtomicOutputsTest, AFailureKeepsTheOldSet) {
  write_set("old");
  EXPECT_THROW(write_directory_atomically(out, names,
                                          [&](const std::filesystem::path& staging) {
                                            write_new_file(staging / "a.txt", [](std::ostream& o) { o << "new"; });
                                            throw UserError("the disk is full");
                                          }),
               UserError);
  EXPECT_EQ(read(out / "a.txt"), "old");
  EXPECT_EQ(entries_in(root), 1u);
}

TEST_F(AtomicOutputsTest, RefusesADirectoryWithFilesItDidNotWrite) {
  std::filesystem::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine";
  EXPECT_THROW(check_replaceable_directory(out, names), UserError);
  EXPECT_THROW(write_set("new"), UserError);
  EXPECT_EQ(read(out / "notes.txt"), "mine");
}

TEST_F(AtomicOutputsTest, StaleTemporariesOfDeadProcessesAreRemovedOthersKept) {
  write_set("current");
  // 999999999 is above any PID Linux hands out: that process is gone.
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  std::string tag = host;
  for (char& c : tag) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  const auto dead = root / (".out.tmp-" + tag + "-999999999-0");
  const auto dead_file = root / (".report.tmp-" + tag + "-999999999-3.json");
  const auto living = temporary_sibling(root / "report.json");  // this process's
  const auto other_host = root / ".out.tmp-elsewhere-999999999-0";
  const auto users_file = root / ".notes.tmp";
  for (const auto& path : {dead, other_host}) std::filesystem::create_directories(path / "inside");
  for (const auto& path : {dead_file, living, users_file}) std::ofstream(path) << "x";
  remove_stale_temporaries(root);
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_FALSE(std::filesystem::exists(dead_file));
  EXPECT_TRUE(std::filesystem::exists(living));
  EXPECT_TRUE(std::filesystem::exists(other_host)) << "another host's process may be alive";
  EXPECT_TRUE(std::filesystem::exists(users_file));

  // A set retired by a process killed between its two renames comes back.
  const auto retired = root / (".gone.old-" + tag + "-999999999-1");
  std::filesystem::create_directories(retired);
  std::ofstream(retired / "a.txt") << "kept";
  remove_stale_temporaries(root);
  EXPECT_EQ(read(root / "gone" / "a.txt"), "kept");
}

// Under the directory's lock (common/directory_lock) no writer of it is
// alive: every temporary is stale, whatever host or PID made it - another
// node of a shared file system, a living PID of another PID namespace, or
// PID 1 of a container (issue 61).
TEST_F(AtomicOutputsTest, InALockedDirectoryEveryTemporaryIsStale) {
  const std::string living = std::to_string(::getppid());  // alive, and not this process
  const auto other_host = root / (".out.tmp-elsewhere-" + living + "-0");
  const auto other_host_file = root / (".summary.tmp-elsewhere-" + living + "-1.json");
  const auto first_of_a_container = root / ".shapes.tmp-elsewhere-1-2";
  const auto users_file = root / ".notes.tmp";
  for (const auto& path : {other_host, first_of_a_container}) std::filesystem::create_directories(path / "inside");
  for (const auto& path : {other_host_file, users_file}) std::ofstream(path) << "x";
  remove_stale_temporaries(root);
  EXPECT_TRUE(std::filesystem::exists(other_host)) << "unlocked, another host's process may be alive";
  remove_stale_temporaries(root, Writers::none);
  EXPECT_FALSE(std::filesystem::exists(other_host));
  EXPECT_FALSE(std::filesystem::exists(other_host_file));
  EXPECT_FALSE(std::filesystem::exists(first_of_a_container));
  EXPECT_TRUE(std::filesystem::exists(users_file)) << "not a name of ours";

  // Beside a locked output set: only that set's temporaries.
  const auto beside = root / (".out.old-elsewhere-" + living + "-3");
  const auto other_set = root / (".other.tmp-elsewhere-" + living + "-4");
  for (const auto& path : {beside, other_set}) std::filesystem::create_directories(path);
  std::filesystem::create_directories(out);
  remove_leftovers_beside(out);
  EXPECT_FALSE(std::filesystem::exists(beside)) << "out is in place: its retired set goes";
  EXPECT_TRUE(std::filesystem::exists(other_set)) << "another output set's";
}

// A swap without exchange killed between its renames on another host: the
// set it retired comes back before the lock is taken.
TEST_F(AtomicOutputsTest, ARetiredSetComesBackWhoeverRetiredIt) {
  const auto retired = root / (".out.old-elsewhere-" + std::to_string(::getppid()) + "-0");
  std::filesystem::create_directories(retired);
  std::ofstream(retired / "a.txt") << "kept";
  restore_retired_directory(out);
  EXPECT_EQ(read(out / "a.txt"), "kept");
  EXPECT_FALSE(std::filesystem::exists(retired));
  // One in place is never replaced.
  std::filesystem::create_directories(retired);
  restore_retired_directory(out);
  EXPECT_TRUE(std::filesystem::exists(retired));
  EXPECT_EQ(read(out / "a.txt"), "kept");
}

TEST_F(AtomicOutputsTest, WritableChecksCreateAFile) {
  EXPECT_NO_THROW(check_writable(root / "file.csv"));
  EXPECT_EQ(entries_in(root), 0u) << "the probe is removed";
  EXPECT_THROW(check_writable(root), UserError);  // a directory
  EXPECT_THROW(check_writable("/proc/meshparticles-probe.csv"), UserError);
  EXPECT_THROW(check_writable(root / "missing" / "file.csv"), UserError);
}

}  // namespace
}  // namespace meshparticles::testing
