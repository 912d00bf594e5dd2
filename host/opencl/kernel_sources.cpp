#include "opencl/kernel_sources.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "common/input_file.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

std::string raw_kernel_file(const std::string& file_name) {
  if (const char* directory = std::getenv("MESHPARTICLES_KERNEL_DIR"); directory && *directory) {
    const std::filesystem::path path = std::filesystem::path(directory) / file_name;
    return read_input_text(path, "kernel " + path.string() + " ($MESHPARTICLES_KERNEL_DIR is set)", "kernel file");
  }
  for (const auto& file : embedded_kernel_files()) {
    if (file_name == file.name) return file.text;
  }
  throw UserError("no kernel file named " + file_name + " is built into this binary");
}

std::string line_marker(int line, const std::string& file_name) {
  return "#line " + std::to_string(line) + " \"" + file_name + "\"\n";
}

// Quoted includes are pasted in place, headers within headers too; the
// headers guard themselves against being included twice. A program is
// several files pasted into one string, so without #line markers a build log
// would count lines of that string ("<source>:71"): each file opens with one,
// and the includer's numbering resumes after each pasted header.
std::string expand_includes(const std::string& file_name, int depth) {
  if (depth > 8) throw UserError("kernel includes nest too deep at " + file_name);
  std::istringstream lines(raw_kernel_file(file_name));
  std::string result = line_marker(1, file_name), line;
  const std::string directive = "#include \"";
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.rfind(directive, 0) == 0) {
      const std::string header = line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
      result += expand_includes(header, depth + 1);
      result += line_marker(number + 1, file_name);
    } else {
      result += line;
      result += '\n';
    }
  }
  return result;
}

}  // namespace

std::string kernel_source(const std::string& file_name) { return expand_includes(file_name, 0); }

std::string name_pasted_lines(const std::string& log, const std::string& source) {
  // Where each line of `source` came from; the markers' own lines too (as
  // the line they announce), so no counted line is left unnamed.
  const std::regex marker(R"re(#line (\d+) "([^"]+)")re");
  std::vector<std::string> origin{""};  // 1-based
  std::istringstream lines(source);
  std::string line, file = "?";
  int number = 1;
  while (std::getline(lines, line)) {
    std::smatch match;
    if (std::regex_match(line, match, marker)) {
      file = match[2];
      number = std::stoi(match[1]);
      origin.push_back(file + ":" + std::to_string(number));
    } else {
      origin.push_back(file + ":" + std::to_string(number++));
    }
  }
  // "<kernel>:8:" and the like: a name in angle brackets, then the line.
  const std::regex counted(R"re(<[A-Za-z _-]+>:(\d+):)re");
  std::string named;
  auto rest = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), counted), end; it != end; ++it) {
    const std::size_t physical = std::stoul((*it)[1]);
    named.append(rest, (*it)[0].first);
    named += physical < origin.size() ? origin[physical] + ":" : it->str();
    rest = (*it)[0].second;
  }
  named.append(rest, log.cend());
  return named;
}

}  // namespace meshparticles
