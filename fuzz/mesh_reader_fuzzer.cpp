// libFuzzer target: one format's reader, the mesh checks, and one fast
// marching solve on whatever they accept. Built once per format with
// FUZZ_FORMAT set (cmake/fuzzing.cmake), so every corpus file is a plain mesh
// file the command line can read too.
//
// A finding is a crash, a sanitizer report, a hang or an allocation over
// libFuzzer's limits, and, checked here: any exception but UserError, a
// message or warning that is not one short line of printable text starting
// with the label, and anything the code writes to std::cout, std::cerr or
// std::clog.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "common/user_error.hpp"
#include "geodesics/fast_marching.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_reader.hpp"

namespace {

using namespace meshparticles;

const std::string kLabel = "fuzz.input";

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "FINDING: %s\n", what.c_str());
  std::abort();
}

// Redirects the standard C++ streams while it lives.
class CapturedStreams {
 public:
  CapturedStreams()
      : out_(std::cout.rdbuf(captured_.rdbuf())),
        err_(std::cerr.rdbuf(captured_.rdbuf())),
        log_(std::clog.rdbuf(captured_.rdbuf())) {}
  ~CapturedStreams() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
    std::clog.rdbuf(log_);
  }
  std::string text() const { return captured_.str(); }

 private:
  std::ostringstream captured_;
  std::streambuf* out_;
  std::streambuf* err_;
  std::streambuf* log_;
};

// A message or warning: one short line of printable text that names the input.
void check_line(const std::string& kind, const std::string& text) {
  if (text.rfind(kLabel + ": ", 0) != 0) finding("a " + kind + " that does not start with the label: " + text);
  for (const char c : text) {
    if (c < 0x20 || c > 0x7e) finding("a " + kind + " with a line break or an unprintable byte: " + text);
  }
  if (text.size() > 400) finding("a " + kind + " of " + std::to_string(text.size()) + " characters: " + text);
}

void read_check_and_solve(std::span<const char> bytes) {
  try {
    std::vector<std::string> warnings;
    const PolygonSoup soup = read_polygon_soup(bytes, MeshFormat::FUZZ_FORMAT, kLabel);
    const SurfaceMesh mesh = build_checked_mesh(soup, kLabel, warnings);
    for (const std::string& warning : warnings) check_line("warning", warning);
    std::vector<double> distances(mesh.vertex_count());
    SolverScratch scratch;
    FastMarching(mesh).solve(0, distances, scratch);
  } catch (const UserError& error) {
    check_line("message", error.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const char> bytes(reinterpret_cast<const char*>(data), size);
  std::string printed;
  {
    CapturedStreams captured;
    try {
      read_check_and_solve(bytes);
    } catch (const std::exception& error) {
      finding(std::string("an exception other than UserError: ") + error.what());
    }
    printed = captured.text();
  }
  if (!printed.empty()) finding("the code printed: " + printed);
  return 0;
}
