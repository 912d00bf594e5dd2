// VTK's legacy format (.vtk), as "VTK File Formats" (the VTK User's Guide)
// defines it, in ASCII or BINARY (big-endian), versions 1.0 to 5.1:
//   # vtk DataFile Version X.Y
//   title
//   ASCII | BINARY
//   DATASET POLYDATA
//   POINTS n type                      float, double or an integer type
//   POLYGONS / TRIANGLE_STRIPS n size  each cell: its count, then its points
//   (5.1: POLYGONS n+1 size, then OFFSETS type and CONNECTIVITY type arrays)
// or DATASET UNSTRUCTURED_GRID (what meshio writes): POINTS, then CELLS
// (the same two layouts) and CELL_TYPES, of which triangles, quads,
// polygons and triangle strips are read, vertices and lines read past, and
// volume or higher-order cells refused by name.
// VERTICES and LINES are read past (they make no surface), as are FIELD
// data and METADATA blocks; POINT_DATA or CELL_DATA ends the geometry, and
// whatever follows is attribute data, not read. Strips become triangles of
// alternating orientation; a strip's triangle with a repeated corner (what
// writers use to join strips) is skipped. Other datasets
// (STRUCTURED_POINTS, ...) are refused by name. Before anything is
// allocated, each count is held against the bytes left (a binary value of k
// bytes needs k; an ASCII value needs two).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "common/user_error.hpp"
#include "mesh/io/binary_values.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

std::optional<ValueType> parse_vtk_type(std::string_view name) {
  static constexpr std::pair<std::string_view, ValueType> kNames[] = {
      {"bit", ValueType::uint8},  // not a numeric array for geometry; refused below by size 0
      {"char", ValueType::int8},          {"unsigned_char", ValueType::uint8},
      {"short", ValueType::int16},        {"unsigned_short", ValueType::uint16},
      {"int", ValueType::int32},          {"unsigned_int", ValueType::uint32},
      {"long", ValueType::int64},         {"unsigned_long", ValueType::uint64},
      {"vtktypeint64", ValueType::int64}, {"vtktypeuint64", ValueType::uint64},
      {"float", ValueType::float32},
      {"double", ValueType::float64}};
  for (const auto& [known, type] : kNames) {
    if (name == known) return type;
  }
  return std::nullopt;
}

class VtkReader {
 public:
  VtkReader(std::span<const char> bytes, const std::string& label) : cursor_(bytes), label_(label) {}

  PolygonSoup read() {
    read_preamble();
    while (const auto keyword = next_keyword()) {
      if (*keyword == "POINTS") {
        read_points();
      } else if (!unstructured_ && (*keyword == "POLYGONS" || *keyword == "TRIANGLE_STRIPS")) {
        read_cells(*keyword == "TRIANGLE_STRIPS");
      } else if (unstructured_ && *keyword == "CELLS") {
        if (cells_) fail("a second CELLS section");
        cells_ = read_cell_arrays("CELLS");
      } else if (unstructured_ && *keyword == "CELL_TYPES") {
        read_cell_types();
      } else if (!unstructured_ && (*keyword == "VERTICES" || *keyword == "LINES")) {
        skip_cells();
      } else if (*keyword == "FIELD") {
        skip_field();
      } else if (*keyword == "METADATA") {
        skip_metadata();
      } else if (*keyword == "POINT_DATA" || *keyword == "CELL_DATA") {
        break;  // attributes follow; the geometry is complete
      } else {
        fail("unexpected " + quoted(*keyword) + " in " + (unstructured_ ? "an UNSTRUCTURED_GRID" : "a POLYDATA") +
             " dataset");
      }
    }
    if (!points_read_) fail("the dataset has no POINTS");
    if (cells_) fail("CELLS without CELL_TYPES");
    return std::move(soup_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw_at_line(label_, cursor_.line_number(), problem); }

  std::string_view next_line_or_fail(const char* what) {
    const auto line = cursor_.next_line();
    if (!line) fail(std::string("file ends before ") + what);
    return *line;
  }

  void read_preamble() {
    cursor_.skip_byte_order_mark();
    const std::string_view version = next_line_or_fail("the header");
    if (version.rfind("# vtk DataFile Version", 0) != 0) {
      fail("expected '# vtk DataFile Version' (a legacy VTK file), got " + quoted(version));
    }
    const auto number = LineTokens(version.substr(22)).next();
    if (const auto value = number ? parse_real(*number) : std::nullopt; value && *value >= 5.0) new_cells_ = true;
    next_line_or_fail("the title");  // anything, up to 256 characters
    LineTokens encoding(next_line_or_fail("ASCII or BINARY"));
    const auto word = encoding.next();
    if (word == "ASCII") {
      binary_ = false;
    } else if (word == "BINARY") {
      binary_ = true;
    } else {
      fail("expected ASCII or BINARY, got " + quoted(word.value_or("")));
    }
    const auto dataset = next_keyword();
    if (dataset != "DATASET") fail("expected DATASET, got " + quoted(dataset.value_or("the end of the file")));
    const auto kind = header_word("the dataset type");
    unstructured_ = kind == "UNSTRUCTURED_GRID";
    if (kind != "POLYDATA" && !unstructured_) {
      fail("DATASET " + quoted(kind) + ": only POLYDATA and UNSTRUCTURED_GRID are read (a surface)");
    }
  }

  // The next keyword: in ASCII any token; in BINARY, after raw data, the
  // next non-blank line's first word (the rest of that line is read with
  // header_word).
  std::optional<std::string_view> next_keyword() {
    if (binary_) {
      while (const auto line = cursor_.next_line()) {
        header_ = LineTokens(*line);
        if (const auto word = header_.next()) return word;
      }
      return std::nullopt;
    }
    return cursor_.next_token();
  }

  // The next word of a keyword's header line (a count, a type name).
  std::string_view header_word(const char* what) {
    const auto word = binary_ ? header_.next() : cursor_.next_token();
    if (!word) fail(std::string("expected ") + what);
    return *word;
  }

  std::size_t header_count(const char* what) {
    const std::string_view word = header_word(what);
    const auto count = parse_integer(word);
    if (!count || *count < 0) fail(std::string("expected ") + what + ", got " + quoted(word));
    return std::size_t(*count);
  }

  ValueType header_type() { return type_of(header_word("a data type")); }
  ValueType type_of(std::string_view word) {
    const auto type = parse_vtk_type(word);
    if (!type || word == "bit") fail("unknown data type " + quoted(word));
    return *type;
  }

  // `count` values fit in the bytes left: k bytes each in binary, two (a
  // digit and a separator) in ASCII. Checked before anything is allocated.
  void check_fits(std::size_t count, ValueType type, const std::string& what) {
    const std::size_t per_value = binary_ ? size_of(type) : 2;
    const std::size_t left = cursor_.remaining() + (binary_ ? 0 : 1);  // no final separator needed
    if (count > left / per_value) {
      fail(what + ": " + plural(count, "value") + ", more than the " + plural(cursor_.remaining(), "byte") +
           " after it can hold (truncated file or corrupt header)");
    }
  }

  const char* binary_values(std::size_t count, ValueType type) {
    const auto bytes = cursor_.next_bytes(count * size_of(type));
    if (!bytes) fail("file ends inside binary data");  // check_fits made this unreachable
    return bytes->data();
  }

  std::string_view ascii_token(const char* what) {
    const auto token = cursor_.next_token();
    if (!token) fail(std::string("file ends before ") + what);
    return *token;
  }

  void read_points() {
    if (points_read_) fail("a second POINTS section");
    const std::size_t count = header_count("the number of points");
    const ValueType type = header_type();
    if (count > SIZE_MAX / 3) fail("too many points");
    check_fits(3 * count, type, "POINTS");
    soup_.vertices.resize(count);
    const std::optional<BinaryValues> binary =
        binary_ ? std::optional(BinaryValues(binary_values(3 * count, type), 3 * count, type, /*big_endian=*/true))
                : std::nullopt;
    std::size_t next = 0;
    const auto coordinate = [&](std::size_t point) {
      if (binary) return binary->real(next++);
      const std::string_view token = ascii_token("the points end");
      const auto value = parse_real(token);
      if (!value) fail("point " + std::to_string(point) + ": expected a number, got " + quoted(token));
      return *value;
    };
    for (std::size_t i = 0; i < count; ++i) {
      Vec3& point = soup_.vertices[i];
      point.x = coordinate(i);
      point.y = coordinate(i);
      point.z = coordinate(i);
    }
    points_read_ = true;
  }

  // `count` integers of `type` (ASCII: any integer token).
  std::vector<long long> read_integers(std::size_t count, ValueType type, const std::string& what) {
    check_fits(count, type, what);
    std::vector<long long> values(count);
    if (binary_) {
      const BinaryValues binary(binary_values(count, type), count, type, /*big_endian=*/true);
      for (std::size_t i = 0; i < count; ++i) {
        const auto value = binary.integer(i);
        if (!value) fail(what + ": value " + std::to_string(i) + " is not an integer index");
        values[i] = *value;
      }
    } else {
      for (std::size_t i = 0; i < count; ++i) {
        const std::string_view token = ascii_token(what.c_str());
        const auto value = parse_integer(token);
        if (!value) fail(what + ": expected an integer, got " + quoted(token));
        values[i] = *value;
      }
    }
    return values;
  }

  // A cell section as (offsets, connectivity): cell c is connectivity
  // [offsets[c], offsets[c + 1]). Version 5 writes them as two arrays;
  // earlier versions write each cell's count before its points.
  std::pair<std::vector<long long>, std::vector<long long>> read_cell_arrays(const std::string& section) {
    const std::size_t first = header_count("a cell count");
    const std::size_t second = header_count("a cell list size");
    std::vector<long long> offsets, connectivity;
    if (new_cells_) {
      // OFFSETS type, first values; CONNECTIVITY type, second values.
      if (next_keyword() != "OFFSETS") fail(section + ": expected OFFSETS");
      offsets = read_integers(first, header_type(), section + " OFFSETS");
      if (next_keyword() != "CONNECTIVITY") fail(section + ": expected CONNECTIVITY");
      connectivity = read_integers(second, header_type(), section + " CONNECTIVITY");
      if (offsets.empty()) offsets.push_back(0);
      if (offsets.front() != 0 || offsets.back() != (long long)(second)) {
        fail(section + ": the offsets do not span the connectivity's " + plural(second, "value"));
      }
      for (std::size_t c = 1; c < offsets.size(); ++c) {
        if (offsets[c] < offsets[c - 1]) fail(section + ": offsets decrease at cell " + std::to_string(c - 1));
      }
      return {std::move(offsets), std::move(connectivity)};
    }
    // first cells in second integers: a count, then that many points, each.
    const std::vector<long long> list = read_integers(second, ValueType::int32, section);
    offsets.reserve(std::min(first, second) + 1);
    connectivity.reserve(second);
    offsets.push_back(0);
    std::size_t at = 0;
    for (std::size_t c = 0; c < first; ++c) {
      if (at >= list.size()) fail(section + ": the list ends after " + plural(c, "cell") + " of " + std::to_string(first));
      const long long size = list[at++];
      if (size < 0 || std::size_t(size) > list.size() - at) {
        fail(section + ": cell " + std::to_string(c) + " claims " + std::to_string(size) + " points, past the list");
      }
      connectivity.insert(connectivity.end(), list.begin() + std::ptrdiff_t(at), list.begin() + std::ptrdiff_t(at + size));
      at += std::size_t(size);
      offsets.push_back((long long)(connectivity.size()));
    }
    if (at != list.size()) {
      fail(section + ": " + plural(first, "cell") + " use " + std::to_string(at) + " of the list's " +
           plural(list.size(), "integer"));
    }
    return {std::move(offsets), std::move(connectivity)};
  }

  // One cell's points: a polygon as one face, a strip as its triangles.
  void add_cell(std::span<const long long> points, bool strip) {
    if (!strip) {
      soup_.face_vertices.insert(soup_.face_vertices.end(), points.begin(), points.end());
      soup_.close_face();
      return;
    }
    for (std::size_t i = 0; i + 2 < points.size(); ++i) {
      const long long a = points[i], b = points[i + 1], d = points[i + 2];
      if (a == b || b == d || a == d) continue;  // joins two strips
      if (i % 2 == 0) {
        soup_.add_triangle(a, b, d);
      } else {
        soup_.add_triangle(b, a, d);
      }
    }
  }

  void read_cells(bool strips) {
    const auto [offsets, connectivity] = read_cell_arrays(strips ? "TRIANGLE_STRIPS" : "POLYGONS");
    for (std::size_t c = 0; c + 1 < offsets.size(); ++c) {
      add_cell(std::span(connectivity).subspan(std::size_t(offsets[c]), std::size_t(offsets[c + 1] - offsets[c])),
               strips);
    }
  }

  // VTK's cell type numbers (vtkCellType.h) that make a surface or nothing.
  enum CellType : long long { kVertex = 1, kPolyVertex = 2, kLine = 3, kPolyLine = 4, kTriangle = 5,
                              kTriangleStrip = 6, kPolygon = 7, kPixel = 8, kQuad = 9 };

  void read_cell_types() {
    if (!cells_) fail("CELL_TYPES before CELLS");
    const auto& [offsets, connectivity] = *cells_;
    const std::size_t cells = offsets.size() - 1;
    if (header_count("the number of cell types") != cells) fail("CELL_TYPES does not count the CELLS' cells");
    const std::vector<long long> types = read_integers(cells, ValueType::int32, "CELL_TYPES");
    for (std::size_t c = 0; c < cells; ++c) {
      const auto points =
          std::span(connectivity).subspan(std::size_t(offsets[c]), std::size_t(offsets[c + 1] - offsets[c]));
      switch (types[c]) {
        case kVertex:
        case kPolyVertex:
        case kLine:
        case kPolyLine:
          break;  // no surface
        case kTriangle:
        case kPolygon:
        case kQuad:
          add_cell(points, false);
          break;
        case kPixel:  // a quad whose corners go row by row
          if (points.size() != 4) fail("cell " + std::to_string(c) + ": a pixel needs 4 points");
          soup_.face_vertices.insert(soup_.face_vertices.end(), {points[0], points[1], points[3], points[2]});
          soup_.close_face();
          break;
        case kTriangleStrip:
          add_cell(points, true);
          break;
        default:
          fail("cell " + std::to_string(c) + " has VTK cell type " + std::to_string(types[c]) +
               ", not a surface cell (triangle, quad, polygon or strip): extract the surface first");
      }
    }
    cells_.reset();
  }

  void skip_cells() { read_cell_arrays("VERTICES or LINES"); }

  // FIELD name arrays; each: name components tuples type, then the values
  // (a "NULL_ARRAY" name has no values), then maybe METADATA.
  void skip_field() {
    header_word("the field's name");
    const std::size_t arrays = header_count("the number of arrays");
    for (std::size_t a = 0; a < arrays; ++a) {
      const auto name = next_keyword();
      if (!name) fail("file ends inside FIELD data");
      if (*name == "METADATA") {
        skip_metadata();
        --a;
        continue;
      }
      if (*name == "NULL_ARRAY") continue;
      const std::size_t components = header_count("the number of components");
      const std::size_t tuples = header_count("the number of tuples");
      if (components != 0 && tuples > SIZE_MAX / components) fail("FIELD array too large");
      const std::string_view type_name = header_word("a data type");
      if (type_name == "string" || type_name == "utf8_string") {  // as VTK's legacy reader takes them
        skip_strings(components * tuples);
        continue;
      }
      const ValueType type = type_of(type_name);
      const std::size_t count = components * tuples;
      check_fits(count, type, "FIELD array");
      if (binary_) {
        binary_values(count, type);
      } else {
        for (std::size_t i = 0; i < count; ++i) ascii_token("the FIELD array ends");
      }
    }
  }

  // A string array's values. ASCII: one per line (escaped, so a line may
  // be empty), after the rest of the header line. BINARY: each string's
  // length, then its bytes (binary_string_length).
  void skip_strings(std::size_t count) {
    if (!binary_) {
      cursor_.next_line();  // the rest of the header line
      for (std::size_t i = 0; i < count; ++i) {
        if (!cursor_.next_line()) fail("file ends inside a FIELD array of strings");
      }
      return;
    }
    if (count > cursor_.remaining()) {  // each string takes a byte at least
      fail("FIELD array of " + plural(count, "string") + ", more than the " + plural(cursor_.remaining(), "byte") +
           " after it can hold");
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint64_t length = binary_string_length();
      if (length > cursor_.remaining() || !cursor_.next_bytes(std::size_t(length))) {
        fail("FIELD string " + std::to_string(i) + " of " + plural(length, "byte") + " runs past the end of the file");
      }
    }
  }

  // A binary string's length as VTK writes it (IO/Legacy/vtkDataWriter.cxx,
  // WriteArray, case VTK_STRING) and reads it (vtkDataReader.cxx, ReadArray,
  // "string"): big-endian in 1, 2, 4 or 8 bytes, as the top two bits of the
  // first byte say (11, 10, 01, 00); those two bits are not part of it.
  std::uint64_t binary_string_length() {
    const auto lead = cursor_.next_bytes(1);
    if (!lead) fail("file ends inside a FIELD array of strings");
    const auto first = static_cast<unsigned char>((*lead)[0]);
    const std::size_t width = std::size_t(1) << (3 - (first >> 6));
    const auto rest = cursor_.next_bytes(width - 1);
    if (!rest) fail("file ends inside a FIELD string's length");
    std::uint64_t length = first & 0x3f;
    for (const char byte : *rest) length = length << 8 | static_cast<unsigned char>(byte);
    return length;
  }

  // METADATA, then lines of information up to an empty line. A section
  // keyword before that line means the empty line is missing: the block
  // would swallow the rest of the file, geometry and all, without a word.
  void skip_metadata() {
    static constexpr std::string_view kSections[] = {"POINTS", "POLYGONS", "TRIANGLE_STRIPS", "VERTICES", "LINES",
                                                     "CELLS", "CELL_TYPES", "FIELD", "POINT_DATA", "CELL_DATA"};
    if (!binary_) cursor_.next_line();  // the rest of the METADATA line
    while (const auto line = cursor_.next_line()) {
      const auto first = LineTokens(*line).next();
      if (first == std::nullopt) return;
      if (std::find(std::begin(kSections), std::end(kSections), *first) != std::end(kSections)) {
        fail("a METADATA block runs into " + std::string(*first) + " without the empty line that ends it");
      }
    }
  }

  ByteCursor cursor_;
  const std::string& label_;
  LineTokens header_{""};
  bool binary_ = false;
  bool unstructured_ = false;  // DATASET UNSTRUCTURED_GRID: CELLS and CELL_TYPES
  std::optional<std::pair<std::vector<long long>, std::vector<long long>>> cells_;  // CELLS until CELL_TYPES
  bool new_cells_ = false;  // version 5: OFFSETS and CONNECTIVITY arrays
  bool points_read_ = false;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_vtk(std::span<const char> bytes, const std::string& label) { return VtkReader(bytes, label).read(); }

}  // namespace meshparticles
