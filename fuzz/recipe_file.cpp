// A recipe's file (its writer, then its byte edits), and what reading that
// file must give when the recipe has no tweaks.
#include <algorithm>

#include "vtk_recipe_writers.hpp"

namespace meshparticles::fuzzing {

namespace {

void edit(std::string& file, const Tweak& tweak) {
  const std::size_t at = (std::size_t(tweak.piece) * 256 + tweak.index) * file.size() / 65536;
  switch (tweak.site) {
    case Site::truncate_file:
      file.resize(at);
      break;
    case Site::flip_byte:
      if (at < file.size()) file[at] = char(file[at] ^ (tweak.how == 0 ? 0xff : tweak.how));
      break;
    case Site::repeat_bytes:
      file.insert(at, file.substr(at, tweak.how));
      break;
    default:
      break;  // a number, not an edit: the writers applied it
  }
}

}  // namespace

std::string write_recipe_file(const Recipe& recipe) {
  std::string file = is_legacy(recipe.encoding) ? write_legacy_vtk(recipe) : write_vtp(recipe);
  for (const Tweak& tweak : recipe.tweaks) edit(file, tweak);
  return file;
}

PolygonSoup expected_soup(const Recipe& recipe) {
  PolygonSoup soup;
  const Mesh& mesh = recipe.mesh;
  for (std::size_t p = 0; p < recipe.pieces; ++p) {
    const auto shift = (long long)soup.vertices.size();
    for (const auto& [x, y, z] : mesh.points) soup.vertices.push_back({x, y, z});
    for (const auto& poly : mesh.polys) {
      for (const long long index : poly) soup.face_vertices.push_back(index + shift);
      soup.close_face();
    }
    for (const auto& strip : mesh.strips) {
      for (std::size_t i = 0; i + 2 < strip.size(); ++i) {
        const long long a = strip[i] + shift, b = strip[i + 1] + shift, c = strip[i + 2] + shift;
        if (a == b || b == c || a == c) continue;
        if (i % 2 == 0) {
          soup.add_triangle(a, b, c);
        } else {
          soup.add_triangle(b, a, c);
        }
      }
    }
  }
  return soup;
}

}  // namespace meshparticles::fuzzing
