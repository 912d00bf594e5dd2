// libFuzzer target: VTK files written from a recipe (vtk_recipe.hpp) and
// read by the legacy or XML reader, then checked as every reader target is
// (fuzz_checks.hpp). One more finding here: a recipe without tweaks is a
// valid file, and the reader must read it exactly (its points and faces),
// not refuse it or read something else.
#include <cstdint>
#include <span>
#include <string>

#include "common/user_error.hpp"
#include "fuzz_checks.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "vtk_recipe_writers.hpp"

namespace {

using namespace meshparticles;

bool same_soup(const PolygonSoup& read, const PolygonSoup& expected) {
  if (read.vertices.size() != expected.vertices.size()) return false;
  for (std::size_t v = 0; v < read.vertices.size(); ++v) {
    const Vec3 &a = read.vertices[v], &b = expected.vertices[v];
    if (a.x != b.x || a.y != b.y || a.z != b.z) return false;
  }
  return read.face_vertices == expected.face_vertices && read.face_starts == expected.face_starts;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshparticles::fuzzing;
  const Recipe recipe = decode_recipe({data, size});
  const std::string file = write_recipe_file(recipe);
  const MeshFormat& format = mesh_format_of(is_legacy(recipe.encoding) ? "recipe.vtk" : "recipe.vtp");
  check_reading([&] {
    PolygonSoup soup;
    try {
      soup = read_polygon_soup(std::span<const char>(file.data(), file.size()), format, kLabel);
    } catch (const UserError& error) {
      if (recipe.valid()) finding(std::string("a valid file refused: ") + error.what() + "\nfile:\n" + file);
      throw;
    }
    if (recipe.valid() && !same_soup(soup, expected_soup(recipe))) finding("a valid file misread:\n" + file);
    check_and_solve(soup);
  });
  return 0;
}
