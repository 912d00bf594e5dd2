// STL, ASCII and binary. A file is binary when its size is exactly what the
// triangle count at byte 80 says (84 + 50 n bytes), whatever its first
// bytes: binary files often begin with "solid" too. Otherwise it must be
// ASCII: solid / facet normal / outer loop / vertex x3 / endloop / endfacet
// / endsolid, keywords in any case, one or more solids. STL has no shared
// vertices: corners with identical coordinates become one vertex, numbered
// in the order first seen.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "common/user_error.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

constexpr std::size_t kBinaryHeaderBytes = 84;    // 80 bytes of text, then the triangle count
constexpr std::size_t kBinaryTriangleBytes = 50;  // normal, three corners, attribute word

class VertexMerger {
 public:
  explicit VertexMerger(PolygonSoup& soup) : soup_(soup) {}
  long long index_of(Vec3 p) {
    // +0.0 turns -0.0 into 0.0: the same position, so the same vertex.
    const Key key{std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
                  std::bit_cast<std::uint64_t>(p.z + 0.0)};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<long long>(soup_.vertices.size()));
    if (inserted) soup_.vertices.push_back(p);
    return it->second;
  }

 private:
  struct Key {
    std::uint64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ k.y) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 32) ^ k.z) * 0x94D049BB133111EBull;
      return std::size_t(h ^ (h >> 31));
    }
  };
  PolygonSoup& soup_;
  std::unordered_map<Key, long long, KeyHash> index_;
};

std::uint32_t little_endian_u32(const char* bytes) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<unsigned char>(bytes[k]);
  return value;
}

float little_endian_float(const char* bytes) { return std::bit_cast<float>(little_endian_u32(bytes)); }

PolygonSoup read_binary_stl(std::span<const char> bytes, std::size_t triangle_count) {
  PolygonSoup soup;
  VertexMerger merger(soup);
  soup.face_starts.reserve(triangle_count + 1);
  for (std::size_t t = 0; t < triangle_count; ++t) {
    const char* corners = bytes.data() + kBinaryHeaderBytes + t * kBinaryTriangleBytes + 12;  // after the normal
    for (int corner = 0; corner < 3; ++corner) {
      const char* p = corners + 12 * corner;
      soup.face_vertices.push_back(
          merger.index_of({little_endian_float(p), little_endian_float(p + 4), little_endian_float(p + 8)}));
    }
    soup.close_face();
  }
  return soup;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::tolower(static_cast<unsigned char>(a[k])) != b[k]) return false;
  }
  return true;
}

class AsciiStlReader {
 public:
  AsciiStlReader(std::span<const char> bytes, const std::string& label)
      : cursor_(bytes), label_(label), merger_(soup_) {}

  PolygonSoup read() {
    expect("solid");
    cursor_.next_line();  // the solid's name
    while (true) {
      const auto keyword = cursor_.next_token();
      if (!keyword) throw UserError(label_ + ": file ends inside a solid (no 'endsolid'; truncated file?)");
      if (equals_ignoring_case(*keyword, "facet")) {
        read_facet();
      } else if (equals_ignoring_case(*keyword, "endsolid")) {
        cursor_.next_line();  // its name
        const auto next = cursor_.next_token();
        if (!next) break;
        if (!equals_ignoring_case(*next, "solid")) unexpected("'solid' or the end of the file", *next);
        cursor_.next_line();
      } else {
        unexpected("'facet' or 'endsolid'", *keyword);
      }
    }
    return std::move(soup_);
  }

 private:
  void read_facet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) read_number();
    expect("outer");
    expect("loop");
    std::size_t corners = 0;
    while (true) {
      const auto keyword = next_keyword();
      if (equals_ignoring_case(keyword, "endloop")) break;
      if (!equals_ignoring_case(keyword, "vertex")) unexpected("'vertex' or 'endloop'", keyword);
      const double x = read_number(), y = read_number(), z = read_number();
      soup_.face_vertices.push_back(merger_.index_of({x, y, z}));
      ++corners;
    }
    if (corners < 3)
      throw_at_line(label_, cursor_.line_number(), "a facet with " + plural(corners, "vertex", "vertices"));
    soup_.close_face();
    expect("endfacet");
  }

  std::string_view next_keyword() {
    const auto token = cursor_.next_token();
    if (!token) throw UserError(label_ + ": file ends inside a facet (truncated file?)");
    return *token;
  }

  void expect(std::string_view keyword) {
    const std::string_view token = next_keyword();
    if (!equals_ignoring_case(token, keyword)) unexpected("'" + std::string(keyword) + "'", token);
  }

  double read_number() {
    const std::string_view token = next_keyword();
    const auto value = parse_real(token);
    if (!value) unexpected("a number", token);
    return *value;
  }

  [[noreturn]] void unexpected(const std::string& expected, std::string_view found) {
    throw_at_line(label_, cursor_.line_number(), "expected " + expected + ", found " + quoted(found));
  }

  ByteCursor cursor_;
  const std::string& label_;
  PolygonSoup soup_;
  VertexMerger merger_;
};

bool starts_with_solid(std::span<const char> bytes) {
  std::size_t k = 0;
  while (k < bytes.size() && is_space(bytes[k])) ++k;
  const std::string_view rest(bytes.data() + k, std::min<std::size_t>(5, bytes.size() - k));
  return equals_ignoring_case(rest, "solid");
}

}  // namespace

PolygonSoup read_stl(std::span<const char> bytes, const std::string& label) {
  if (bytes.size() >= kBinaryHeaderBytes) {
    const std::size_t triangles = little_endian_u32(bytes.data() + 80);
    if (bytes.size() == kBinaryHeaderBytes + triangles * kBinaryTriangleBytes) return read_binary_stl(bytes, triangles);
    if (!starts_with_solid(bytes)) {
      throw UserError(label + ": binary STL header declares " + plural(triangles, "triangle") + " (" +
                      std::to_string(kBinaryHeaderBytes + triangles * kBinaryTriangleBytes) +
                      " bytes) but the file has " + plural(bytes.size(), "byte") + " (truncated file?)");
    }
  } else if (!starts_with_solid(bytes)) {
    throw UserError(label + ": not an STL file (too short for binary, and it does not begin with 'solid')");
  }
  return AsciiStlReader(bytes, label).read();
}

}  // namespace meshparticles
