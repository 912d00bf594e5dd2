// kernel_source() pastes headers into one string for the OpenCL compiler;
// its #line markers must give every line of that string back its own file
// and line number, which is what a build log prints. Checked line by line
// against the files in kernels/.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "opencl/kernel_sources.hpp"

namespace meshparticles::testing {
namespace {

std::vector<std::string> lines_of_kernel_file(const std::string& name) {
  std::ifstream in(std::string(KERNELS_DIR) + "/" + name);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(KernelSources, EveryPastedLineKeepsItsFileAndLineNumber) {
  const std::regex marker(R"re(#line (\d+) "([^"]+)")re");
  std::map<std::string, std::vector<std::string>> originals;
  for (const auto& file : embedded_kernel_files()) {
    SCOPED_TRACE(file.name);
    std::istringstream expanded(kernel_source(file.name));
    std::string line, at_file;
    std::size_t at_line = 0, markers = 0;
    while (std::getline(expanded, line)) {
      std::smatch match;
      if (std::regex_match(line, match, marker)) {
        at_file = match[2];
        at_line = std::stoul(match[1]);
        ++markers;
        continue;
      }
      ASSERT_FALSE(at_file.empty()) << "a line before the first #line marker: " << line;
      auto& original = originals[at_file];
      if (original.empty()) original = lines_of_kernel_file(at_file);
      ASSERT_LE(at_line, original.size()) << at_file << " has no line " << at_line << ": '" << line << "'";
      EXPECT_EQ(line, original[at_line - 1]) << "labelled " << at_file << ":" << at_line;
      EXPECT_NE(line.rfind("#include \"", 0), 0u) << "not pasted: " << line;
      ++at_line;
    }
    EXPECT_GE(markers, 1u);
  }
}

}  // namespace
}  // namespace meshparticles::testing
