#include "fuzz_checks.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <vector>

#include "common/user_error.hpp"
#include "geodesics/fast_marching.hpp"
#include "mesh/mesh_checks.hpp"

namespace meshparticles::fuzzing {

namespace {

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
  CapturedStreams(const CapturedStreams&) = delete;
  CapturedStreams& operator=(const CapturedStreams&) = delete;
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

}  // namespace

void finding(const std::string& what) {
  std::fprintf(stderr, "FINDING: %s\n", what.c_str());
  std::abort();
}

void check_reading(const std::function<void()>& read) {
  std::string printed;
  {
    CapturedStreams captured;
    try {
      read();
    } catch (const UserError& error) {
      check_line("message", error.what());
    } catch (const std::exception& error) {
      finding(std::string("an exception other than UserError: ") + error.what());
    }
    printed = captured.text();
  }
  if (!printed.empty()) finding("the code printed: " + printed);
}

void check_and_solve(const PolygonSoup& soup) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = build_checked_mesh(soup, kLabel, warnings);
  for (const std::string& warning : warnings) check_line("warning", warning);
  std::vector<double> distances(mesh.vertex_count());
  SolverScratch scratch;
  FastMarching(mesh).solve(0, distances, scratch);
}

}  // namespace meshparticles::fuzzing
