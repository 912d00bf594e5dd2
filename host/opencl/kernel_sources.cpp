#include "opencl/kernel_sources.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

std::string raw_kernel_file(const std::string& file_name) {
  if (const char* directory = std::getenv("MESHPARTICLES_KERNEL_DIR"); directory && *directory) {
    const std::filesystem::path path = std::filesystem::path(directory) / file_name;
    std::ifstream in(path);
    if (!in) throw UserError("cannot read kernel " + path.string() + " ($MESHPARTICLES_KERNEL_DIR is set)");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
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

}  // namespace meshparticles
