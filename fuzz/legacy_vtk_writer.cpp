// A recipe as a legacy .vtk file, laid out as VTK's vtkDataWriter writes
// one: header, FIELD data, POINTS (and METADATA), then the cell sections,
// then attributes. Binary values are big-endian, each array followed by a
// newline.
#include <utility>

#include "recipe_values.hpp"
#include "vtk_recipe_writers.hpp"

namespace meshparticles::fuzzing {

namespace {

// The strings of the FIELD array of strings; the last holds a line break,
// which ASCII escapes and binary writes as it is.
const std::string kStrings[] = {"alpha", "", "two words", std::string(70, 'v'), "new\nline"};

// A string as vtkDataWriter::EncodeString writes it in ASCII: a space,
// a line break and '%' as %XX.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == ' ' || c == '\n' || c == '%') {
      char code[4];
      std::snprintf(code, sizeof code, "%%%02X", unsigned(c));
      out += code;
    } else {
      out += c;
    }
  }
  return out;
}

// A cell section's identity for tweaks (Where::index, of kSections).
enum Section : std::size_t { kPolygons, kStrips, kVertices, kLines, kCells, kSections };

class LegacyWriter {
 public:
  explicit LegacyWriter(const Recipe& recipe)
      : recipe_(recipe), binary_(recipe.encoding == Encoding::legacy_binary), mesh_(recipe.mesh) {}

  std::string write() {
    out_ = std::string("# vtk DataFile Version ") + (recipe_.version_5 ? "5.1" : "4.2") +
           "\nwritten by the structured fuzzer\n" + (binary_ ? "BINARY" : "ASCII") + "\nDATASET " +
           (recipe_.unstructured ? "UNSTRUCTURED_GRID" : "POLYDATA") + "\n";
    if (recipe_.field_data) field_data();
    points();
    if (recipe_.unstructured) {
      grid_cells();
    } else {
      if (recipe_.verts_and_lines) {
        cells("VERTICES", kVertices, {{0}});
        cells("LINES", kLines, {{0, 1}});
      }
      if (!mesh_.polys.empty()) cells("POLYGONS", kPolygons, mesh_.polys);
      if (!mesh_.strips.empty()) cells("TRIANGLE_STRIPS", kStrips, mesh_.strips);
    }
    if (recipe_.attributes_after) attributes();
    return std::move(out_);
  }

 private:
  long long tweaked(Site site, std::size_t index, std::size_t of, long long actual, long long related = 0) const {
    return recipe_.tweaked(site, {0, index, of}, actual, related);
  }

  void integers(const std::vector<long long>& values, ValueType type) {
    for (const long long value : values) {
      if (binary_) {
        append_binary(out_, type, 0, value, true);
      } else {
        out_ += std::to_string(value) + " ";
      }
    }
    out_ += "\n";
  }

  void reals(const std::vector<double>& values, ValueType type) {
    for (const double value : values) {
      if (binary_) {
        append_binary(out_, type, value, 0, true);
      } else {
        out_ += real_text(value) + " ";
      }
    }
    out_ += "\n";
  }

  std::vector<double> coordinates() const {
    std::vector<double> values;
    for (const auto& point : mesh_.points) values.insert(values.end(), point.begin(), point.end());
    return values;
  }

  void points() {
    const long long n = (long long)mesh_.points.size();
    out_ += "POINTS " + std::to_string(tweaked(Site::point_count, 0, 1, n, 3 * n)) +
            (recipe_.points_double ? " double\n" : " float\n");
    reals(coordinates(), recipe_.points_double ? ValueType::float64 : ValueType::float32);
    if (recipe_.metadata) out_ += "METADATA\nCOMPONENT_NAMES\nx\ny\nz\nINFORMATION 0\n\n";
  }

  // A cell section: before 5.0 one list of (count, points...) in int;
  // from 5.0 the cell count plus one, and OFFSETS and CONNECTIVITY arrays.
  void cells(const std::string& keyword, Section section, const std::vector<std::vector<long long>>& cells) {
    std::vector<long long> offsets{0}, connectivity, list;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto& cell = cells[c];
      list.push_back(tweaked(Site::cell_size, c, 256, (long long)cell.size()));
      for (const long long index : cell) {
        const long long point =
            tweaked(Site::connectivity_value, connectivity.size(), 256, index, (long long)mesh_.points.size());
        connectivity.push_back(point);
        list.push_back(point);
      }
      offsets.push_back(tweaked(Site::offset_value, offsets.size(), 256, (long long)connectivity.size(),
                                offsets.back()));
    }
    const long long count = recipe_.version_5 ? (long long)offsets.size() : (long long)cells.size();
    const long long size = recipe_.version_5 ? (long long)connectivity.size() : (long long)list.size();
    out_ += keyword + " " + std::to_string(tweaked(Site::cell_count, section, kSections, count, size)) + " " +
            std::to_string(tweaked(Site::cell_list_size, section, kSections, size, count)) + "\n";
    if (!recipe_.version_5) return integers(list, ValueType::int32);
    const ValueType type = index_type_of(recipe_.index_type);
    static constexpr const char* kTypeNames[] = {"int", "vtktypeint64", "unsigned_int", "vtktypeuint64"};
    const std::string type_name = kTypeNames[recipe_.index_type % 4];
    out_ += "OFFSETS " + type_name + "\n";
    integers(offsets, type);
    out_ += "CONNECTIVITY " + type_name + "\n";
    integers(connectivity, type);
  }

  // UNSTRUCTURED_GRID: every cell in one CELLS section, then their types
  // (vtkCellType.h: triangle 5, strip 6, polygon 7, quad 9, vertex 1, line 3).
  void grid_cells() {
    std::vector<std::vector<long long>> all;
    std::vector<long long> types;
    for (const auto& poly : mesh_.polys) {
      all.push_back(poly);
      types.push_back(poly.size() == 3 ? 5 : poly.size() == 4 ? 9 : 7);
    }
    for (const auto& strip : mesh_.strips) {
      all.push_back(strip);
      types.push_back(6);
    }
    if (recipe_.verts_and_lines) {
      all.push_back({0});
      types.push_back(1);
      all.push_back({0, 1});
      types.push_back(3);
    }
    cells("CELLS", kCells, all);
    for (std::size_t c = 0; c < types.size(); ++c) types[c] = tweaked(Site::cell_type, c, 256, types[c]);
    const long long n = (long long)types.size();
    out_ += "CELL_TYPES " + std::to_string(tweaked(Site::cell_type_count, 0, 1, n, n)) + "\n";
    integers(types, ValueType::int32);
  }

  // FIELD data at the dataset level: a numeric array (with METADATA when
  // the recipe has it) and an array of strings.
  void field_data() {
    const long long n = (long long)mesh_.points.size(), strings = std::size(kStrings);
    out_ += "FIELD FieldData 2\n";
    out_ += "temperature " + std::to_string(tweaked(Site::component_count, 0, 2, 1)) + " " +
            std::to_string(tweaked(Site::tuple_count, 0, 2, n, 3 * n)) + " float\n";
    reals(std::vector<double>(std::size_t(n), 1.5), ValueType::float32);
    if (recipe_.metadata) out_ += "METADATA\nINFORMATION 0\n\n";
    out_ += "names " + std::to_string(tweaked(Site::component_count, 1, 2, 1)) + " " +
            std::to_string(tweaked(Site::tuple_count, 1, 2, strings, strings + 1)) + " string\n";
    for (std::size_t s = 0; s < std::size(kStrings); ++s) {
      if (!binary_) {
        out_ += escaped(kStrings[s]) + "\n";
        continue;
      }
      string_length(s, kStrings[s].size());
      out_ += kStrings[s];
    }
    if (binary_) out_ += "\n";
  }

  // vtkDataWriter's length prefix: the top two bits of the first byte give
  // its width (11: 1 byte, 10: 2, 01: 4, 00: 8), the rest the length, big-endian.
  void string_length(std::size_t s, std::size_t actual) {
    const auto length = (unsigned long long)tweaked(Site::string_length, s, 8, (long long)actual, 0);
    const std::size_t fewest = length < (1u << 6) ? 1 : length < (1u << 14) ? 2 : length < (1u << 30) ? 4 : 8;
    const std::size_t width = std::max(fewest, recipe_.string_width == 0 ? 1 : std::size_t(1) << recipe_.string_width);
    if (width == 1) append_raw(out_, std::uint8_t(0xc0 | length), true);
    if (width == 2) append_raw(out_, std::uint16_t(0x8000 | length), true);
    if (width == 4) append_raw(out_, std::uint32_t(0x40000000 | length), true);
    if (width == 8) append_raw(out_, std::uint64_t(length), true);
  }

  void attributes() {
    out_ += "POINT_DATA " + std::to_string(mesh_.points.size()) + "\nSCALARS height float 1\nLOOKUP_TABLE default\n";
    reals(std::vector<double>(mesh_.points.size(), 2.0), ValueType::float32);
  }

  const Recipe& recipe_;
  const bool binary_;
  const Mesh& mesh_;
  std::string out_;
};

}  // namespace

std::string write_legacy_vtk(const Recipe& recipe) { return LegacyWriter(recipe).write(); }

}  // namespace meshparticles::fuzzing
