// Hard edges from the environment (issue 34): files that are not regular
// files, memory limits the process runs under, threads the system refuses,
// the OpenCL runtime's environment, and text that must stay on one line.
// Limits are set in death-test children (fork), never in the test process.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <optional>
#include <string>

#include "common/input_file.hpp"
#include "common/memory_limits.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "common/worker_threads.hpp"
#include "geodesics/distance_table.hpp"
#include "geodesics/memory_guard.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "opencl/runtime_environment.hpp"

namespace meshparticles::testing {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path() /
                         ("meshparticles_hard_edges_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::string message_of(const std::function<void()>& work) {
  try {
    work();
  } catch (const UserError& error) {
    return error.what();
  }
  return "(nothing thrown)";
}

// The address space this process maps now, from /proc/self/status.
std::uint64_t mapped_bytes() {
  std::ifstream status("/proc/self/status");
  for (std::string key; status >> key;) {
    std::uint64_t kibibytes = 0;
    if (key == "VmSize:" && status >> kibibytes) return kibibytes * 1024;
  }
  return 0;
}

// AddressSanitizer reserves terabytes of address space for its shadow and
// maps more as it allocates: a process under it cannot be given an
// address-space limit. These tests run in the normal build (and in CI's
// first pass); the sanitizer pass leaves them out, saying why.
// GCC says so with __SANITIZE_ADDRESS__, clang with __has_feature.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESHPARTICLES_TESTS_UNDER_ASAN
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(MESHPARTICLES_TESTS_UNDER_ASAN)
constexpr bool kUnderAddressSanitizer = true;
#else
constexpr bool kUnderAddressSanitizer = false;
#endif
#define SKIP_UNDER_ADDRESS_SANITIZER() \
  if (kUnderAddressSanitizer) GTEST_SKIP() << "no address-space limit under AddressSanitizer (it reserves terabytes)"

void limit_address_space(std::uint64_t bytes) {
  const struct rlimit limit { bytes, bytes };
  if (::setrlimit(RLIMIT_AS, &limit) != 0) std::_Exit(90);
}

TEST(InputFile, RefusesAFifoAtOnceNamingIt) {
  const auto directory = scratch("fifo");
  const auto fifo = directory / "points.particles";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto started = std::chrono::steady_clock::now();
  EXPECT_EQ(message_of([&] { read_input_text(fifo, "LABEL"); }),
            "LABEL: not a regular file (a device, FIFO or socket), refused: reading it might never end");
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
  EXPECT_EQ(message_of([&] { read_input_text(directory, "LABEL", "particle file"); }),
            "LABEL: is a directory, not a particle file");
  EXPECT_EQ(message_of([&] { read_input_text(directory / "missing", "LABEL"); }), "LABEL: no such file");
  EXPECT_EQ(message_of([&] { read_input_text("/dev/zero", "LABEL"); }).find("LABEL: not a regular file"), 0u);
  std::filesystem::remove_all(directory);
}

TEST(InputFile, ReadsARegularFileWholeAndRefusesOneOverItsLimit) {
  const auto directory = scratch("regular");
  const auto file = directory / "list.txt";
  std::ofstream(file) << "a.off\nb.off\n";
  EXPECT_EQ(read_input_text(file, "LABEL"), "a.off\nb.off\n");
  EXPECT_EQ(message_of([&] { read_input_text(file, "LABEL", "mesh list", 5); }),
            "LABEL: 12 bytes, more than the 5 bytes a mesh list may have");
  std::filesystem::remove_all(directory);
}

TEST(OneLine, EscapesControlCharacters) {
  EXPECT_EQ(one_line("a\nb\rc\td\x01" "e\x7f"), "a\\nb\\rc\\td\\x01e\\x7f");
  EXPECT_EQ(one_line("plain text, é"), "plain text, é");
}

TEST(MemoryLimits, AnAddressSpaceLimitIsWhatSetsTheRoom) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  EXPECT_EXIT(
      {
        const std::uint64_t room = 256ull << 20;
        limit_address_space(mapped_bytes() + room);
        const MemoryRoom found = memory_room();
        if (found.set_by.find("the address-space limit (ulimit -v ") != 0) std::_Exit(1);
        if (found.bytes > room || found.bytes < room / 2) std::_Exit(2);
        if (usable_host_memory_name().find("the room under the address-space limit") != 0) std::_Exit(3);
        if (!address_space_limit_bytes()) std::_Exit(4);
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(MemoryLimits, ATableOverTheLimitIsRefusedBeforeItIsAllocated) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  EXPECT_EXIT(
      {
        limit_address_space(mapped_bytes() + (64ull << 20));
        try {
          check_table_fits(8000, 4, usable_host_memory_bytes(), "distance table", usable_host_memory_name());
        } catch (const MemoryRefusal& refusal) {
          const std::string message = refusal.what();
          std::_Exit(message.find("needs 0.24 GiB but the room under the address-space limit") == std::string::npos);
        }
        std::_Exit(5);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(MemoryLimits, OutOfMemoryIsSaidWithTheFileAndTheStage) {
  EXPECT_EQ(message_of([] { naming_memory_failures("mesh.off", "computing distances", [] { throw std::bad_alloc(); }); })
                .find("mesh.off: out of memory while computing distances ("),
            0u);
  EXPECT_EQ(message_of([] {
              naming_memory_failures("mesh.off", "planning the run", [] { throw MemoryRefusal("the table needs more"); });
            }),
            "mesh.off: the table needs more");
  EXPECT_EQ(naming_memory_failures("mesh.off", "adding", [] { return 1 + 1; }), 2);
}

TEST(WorkerThreads, StartAsManyAsTheSystemAllowsAndJoinThem) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  EXPECT_EXIT(
      {
        // 24 MiB more than is mapped: room for two or three 8 MiB stacks.
        limit_address_space(mapped_bytes() + (24ull << 20));
        std::atomic<int> ran{0};
        WorkerThreads refused(64, [&](unsigned) { ++ran; });
        refused.join();
        std::_Exit(refused.started() > 0 && refused.started() < 64 && ran == int(refused.started()) ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(WorkerThreads, AllPairsWithThreadsRefusedIsTheSameTable) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(std::string(MESHES_DIR) + "/torus.off", warnings);
  const DistanceTable expected = compute_all_pairs(mesh, GeodesicMethod::fast_marching, 1, /*quiet=*/true);
  EXPECT_EXIT(
      {
        // The table (9 MiB) fits; sixteen 8 MiB stacks do not. Before,
        // a refused thread ended the process in std::terminate.
        limit_address_space(mapped_bytes() + (48ull << 20));
        const DistanceTable table = compute_all_pairs(mesh, GeodesicMethod::fast_marching, 16, /*quiet=*/true);
        for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
          for (VertexId w = 0; w < mesh.vertex_count(); ++w) {
            if (table(v, w) != expected(v, w)) std::_Exit(2);
          }
        }
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "");
}

// Restores an environment variable when the test ends.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value, 1);
  }
  ~ScopedEnvironment() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(RuntimeEnvironment, APoclCacheDirPoclCannotUseIsNamed) {
  const auto directory = scratch("pocl");
  {
    const ScopedEnvironment empty("POCL_CACHE_DIR", "");
    ASSERT_TRUE(runtime_environment_problem());
    EXPECT_EQ(runtime_environment_problem()->find("$POCL_CACHE_DIR is set but empty"), 0u);
  }
  std::ofstream(directory / "file") << "x";
  {
    const ScopedEnvironment file("POCL_CACHE_DIR", (directory / "file").c_str());
    ASSERT_TRUE(runtime_environment_problem());
    EXPECT_NE(runtime_environment_problem()->find("is not a directory"), std::string::npos);
  }
  {
    const ScopedEnvironment under_file("POCL_CACHE_DIR", (directory / "file" / "sub").c_str());
    EXPECT_TRUE(runtime_environment_problem());
  }
  {
    const ScopedEnvironment missing("POCL_CACHE_DIR", (directory / "new" / "cache").c_str());
    EXPECT_FALSE(runtime_environment_problem()) << *runtime_environment_problem();  // PoCL makes it
  }
  std::filesystem::remove_all(directory);
}

TEST(RuntimeEnvironment, AnAddressSpaceLimitUnderWhatOpenClNeedsIsNamed) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  EXPECT_EXIT(
      {
        limit_address_space(kOpenClMinimumAddressSpace / 2);
        const auto problem = runtime_environment_problem();
        std::_Exit(problem && problem->find("--backend serial-field") != std::string::npos ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace meshparticles::testing
