// libFuzzer target: one format's reader, the mesh checks, and one fast
// marching solve on whatever they accept. Built once per format with
// FUZZ_EXTENSION set (cmake/fuzzing.cmake), so every corpus file is a plain mesh
// file the command line can read too. What counts as a finding:
// fuzz_checks.hpp.
#include <cstdint>
#include <span>

#include "fuzz_checks.hpp"
#include "mesh/io/mesh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshparticles;
  const std::span<const char> bytes(reinterpret_cast<const char*>(data), size);
  fuzzing::check_reading([&] {
    fuzzing::check_and_solve(read_polygon_soup(bytes, mesh_format_of("input" FUZZ_EXTENSION), fuzzing::kLabel));
  });
  return 0;
}
