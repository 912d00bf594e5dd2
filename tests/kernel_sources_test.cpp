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

// NVIDIA's compiler ignores #line and counts the lines of the whole pasted
// program ("<kernel>:8:1: error"): the log is given back with each counted
// line named by its file and line, as PoCL names them itself.
TEST(KernelSources, ALogThatCountsPastedLinesNamesTheirFiles) {
  const std::string source = kernel_source("naive_update.cl") + kernel_source("apply_moves.cl");
  std::istringstream pasted(source);
  std::string line;
  std::size_t physical = 0, header_line = 0, second_file_line = 0;
  const std::vector<std::string> claims = lines_of_kernel_file("claims.h");
  const std::vector<std::string> apply = lines_of_kernel_file("apply_moves.cl");
  bool in_apply_moves = false;
  while (std::getline(pasted, line)) {
    ++physical;
    if (line == "#line 1 \"apply_moves.cl\"") in_apply_moves = true;
    if (header_line == 0 && line == claims[2]) header_line = physical;
    if (in_apply_moves && second_file_line == 0 && line == apply[3]) second_file_line = physical;
  }
  ASSERT_GT(header_line, 0u);
  ASSERT_GT(second_file_line, 0u);
  const std::string log = "<kernel>:" + std::to_string(header_line) + ":7: error: one\n" +
                          "<kernel>:" + std::to_string(second_file_line) + ":1: warning: two\n" +
                          "<kernel>:99999:1: error: past the end\n";
  EXPECT_EQ(name_pasted_lines(log, source),
            "claims.h:3:7: error: one\napply_moves.cl:4:1: warning: two\n<kernel>:99999:1: error: past the end\n");
  const std::string pocl = "field.h:3:1: error: unknown type name 'this'\n";
  EXPECT_EQ(name_pasted_lines(pocl, source), pocl);
}

}  // namespace
}  // namespace meshparticles::testing
