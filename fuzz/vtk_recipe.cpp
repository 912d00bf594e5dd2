#include "vtk_recipe.hpp"

#include <climits>

namespace meshparticles::fuzzing {

namespace {

// The input's bytes in order; 0 past the end.
class RecipeBytes {
 public:
  explicit RecipeBytes(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint8_t next() { return at_ < bytes_.size() ? bytes_[at_++] : 0; }
  std::size_t left() const { return bytes_.size() - at_; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

// The default mesh, a closed tetrahedron; its strip covers it too.
Mesh tetrahedron() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
          {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}},
          {{0, 1, 2, 3, 0, 1}}};
}

// A w x h grid of points, cut into quads or triangles, and a strip per row.
Mesh grid(std::size_t w, std::size_t h, bool quads) {
  Mesh mesh;
  const auto at = [w](std::size_t x, std::size_t y) { return (long long)(y * w + x); };
  for (std::size_t y = 0; y < h; ++y) {
    for (std::size_t x = 0; x < w; ++x) mesh.points.push_back({double(x), double(y), 0.5 * double(x)});
  }
  for (std::size_t y = 0; y + 1 < h; ++y) {
    std::vector<long long> strip;
    for (std::size_t x = 0; x + 1 < w; ++x) {
      const long long a = at(x, y), b = at(x + 1, y), c = at(x + 1, y + 1), d = at(x, y + 1);
      if (quads) {
        mesh.polys.push_back({a, b, c, d});
      } else {
        mesh.polys.push_back({a, b, c});
        mesh.polys.push_back({a, c, d});
      }
    }
    for (std::size_t x = 0; x < w; ++x) {
      strip.push_back(at(x, y + 1));
      strip.push_back(at(x, y));
    }
    mesh.strips.push_back(strip);
  }
  return mesh;
}

Mesh decode_mesh(std::uint8_t shape, std::uint8_t cells) {
  Mesh mesh = shape % 3 == 0 ? tetrahedron() : grid(2 + shape / 3 % 3, 2 + shape / 9 % 3, shape % 3 == 2);
  // Polygons, strips or both.
  if (cells % 3 == 0) mesh.strips.clear();
  if (cells % 3 == 1) mesh.polys.clear();
  return mesh;
}

long long apply(std::uint8_t how, long long actual, long long related) {
  // Wrapping arithmetic, as a writer's bug would wrap.
  const auto plus = [](long long a, long long b) { return (long long)((unsigned long long)a + (unsigned long long)b); };
  switch (how % 14) {
    case 0: return plus(actual, -1);
    case 1: return plus(actual, 1);
    case 2: return plus(actual, -2);
    case 3: return plus(actual, 2);
    case 4: return 0;
    case 5: return -1;
    case 6: return related;
    case 7: return plus(related, actual);
    case 8: return plus(actual, actual);
    case 9: return INT_MAX;
    case 10: return 1LL << 32;
    case 11: return LLONG_MAX;
    case 12: return LLONG_MIN;  // 2^63 as an unsigned value
    default: return plus(actual, 1LL << 62);
  }
}

}  // namespace

long long Recipe::tweaked(Site site, Where where, long long actual, long long related) const {
  for (const Tweak& tweak : tweaks) {
    if (tweak.site == site && tweak.piece % pieces == where.piece && tweak.index % where.of == where.index) {
      actual = apply(tweak.how, actual, related);
    }
  }
  return actual;
}

Recipe decode_recipe(std::span<const std::uint8_t> bytes) {
  RecipeBytes input(bytes);
  Recipe recipe;
  recipe.encoding = Encoding(input.next() % kEncodings);
  const std::uint8_t layout = input.next();
  recipe.compressed = layout & 1;
  recipe.header_uint64 = layout & 2;
  recipe.big_endian = layout & 4;
  recipe.split_base64 = layout & 8;
  recipe.version_5 = layout & 16;
  recipe.unstructured = layout & 32;
  recipe.points_double = layout & 64;
  recipe.index_type = input.next() % 4;
  const std::uint8_t shape = input.next(), cells = input.next();
  recipe.mesh = decode_mesh(shape, cells);
  const std::uint8_t pieces = input.next();
  recipe.pieces = is_legacy(recipe.encoding) ? 1 : 1 + pieces % 3;  // a legacy file is one piece
  const std::uint8_t extras = input.next();
  recipe.verts_and_lines = extras & 1;
  recipe.field_data = extras & 2;
  recipe.metadata = extras & 4;
  recipe.attributes_after = extras & 8;
  recipe.string_width = extras >> 6;
  // Small blocks make several of them: the compressed header's edge cases.
  const std::uint8_t block = input.next();
  recipe.block_size = block == 0 ? 32768 : 4 * std::size_t(block);
  while (input.left() >= 4) {
    Tweak tweak{Site(input.next() % kSites), input.next(), input.next(), input.next()};
    recipe.tweaks.push_back(tweak);
  }
  return recipe;
}

}  // namespace meshparticles::fuzzing
