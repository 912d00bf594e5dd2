#pragma once
// What every fuzz target of the mesh readers checks, in one place: the
// finding rules of docs/MESHES.md ("Fuzzing"). A finding is a crash, a
// sanitizer report, a hang or an allocation over libFuzzer's limits, and,
// checked here: any exception but UserError, a message or warning that is
// not one short line of printable text starting with the label, and
// anything the code writes to std::cout, std::cerr or std::clog.
#include <functional>
#include <string>

#include "mesh/polygon_soup.hpp"

namespace meshparticles::fuzzing {

// The label every message must start with.
inline const std::string kLabel = "fuzz.input";

// Reports a finding on stderr and aborts, so libFuzzer keeps the input.
[[noreturn]] void finding(const std::string& what);

// Runs `read` (a reader and whatever follows it) with the standard streams
// captured; a UserError it throws must be one good line, and anything else
// it throws or prints is a finding.
void check_reading(const std::function<void()>& read);

// The mesh checks and one fast marching solve on a soup the reader
// accepted; their warnings must be good lines too.
void check_and_solve(const PolygonSoup& soup);

}  // namespace meshparticles::fuzzing
