// PLY as Greg Turk defined it (and Paul Bourke documents it): a text header,
// then each element's records in header order, in ASCII or in binary of
// either byte order, properties of any of the eight numeric types.
//   vertex:    x, y, z (any numeric type)
//   face:      a list property vertex_indices (or vertex_index)
//   tristrips: a list property vertex_indices; -1 ends one strip and starts
//              the next; triangles with a repeated corner (what writers use
//              to join strips) are skipped
// Every other element and property, lists included, is read past. Before
// anything is allocated, the header's counts are held against the bytes
// after it (a binary record of k bytes needs k; an ASCII value needs two).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "common/user_error.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

std::optional<PlyType> parse_ply_type(std::string_view name) {
  static constexpr std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::int8},      {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},    {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16},  {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},    {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32},  {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64}};
  for (const auto& [known, type] : kNames) {
    if (name == known) return type;
  }
  return std::nullopt;
}

std::size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 0;
}

bool is_integer_type(PlyType type) { return type != PlyType::float32 && type != PlyType::float64; }

template <typename T>
T load(const char* bytes, bool swap) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), bytes, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  return std::bit_cast<T>(raw);
}

double decode(PlyType type, const char* bytes, bool swap) {
  switch (type) {
    case PlyType::int8:
      return load<std::int8_t>(bytes, swap);
    case PlyType::uint8:
      return load<std::uint8_t>(bytes, swap);
    case PlyType::int16:
      return load<std::int16_t>(bytes, swap);
    case PlyType::uint16:
      return load<std::uint16_t>(bytes, swap);
    case PlyType::int32:
      return load<std::int32_t>(bytes, swap);
    case PlyType::uint32:
      return load<std::uint32_t>(bytes, swap);
    case PlyType::float32:
      return load<float>(bytes, swap);
    case PlyType::float64:
      return load<double>(bytes, swap);
  }
  return 0;
}

// A value used as a count or an index: a whole number a long long holds.
std::optional<long long> as_whole_number(double value) {
  constexpr double kLimit = 9.0e15;  // below 2^53: every whole number here is exact
  if (!(value >= -kLimit && value <= kLimit) || value != std::trunc(value)) return std::nullopt;
  return static_cast<long long>(value);
}

struct PlyProperty {
  std::string name;
  PlyType type;
  std::optional<PlyType> list_count_type;  // set for a list property
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

class PlyReader {
 public:
  PlyReader(std::span<const char> bytes, const std::string& label) : cursor_(bytes), label_(label) {}

  PolygonSoup read() {
    read_header();
    check_counts_fit();
    for (const PlyElement& element : elements_) read_element(element);
    // Like the header's counts say: read past, with a word.
    if (encoding_ == PlyEncoding::ascii ? cursor_.next_token().has_value() : !cursor_.at_end()) {
      soup_.warnings.push_back(label_ + ": data after the elements the header declares ignored");
    }
    return std::move(soup_);
  }

 private:
  void read_header() {
    cursor_.skip_byte_order_mark();
    const auto magic = cursor_.next_line();
    if (!magic || trimmed(*magic) != "ply") throw UserError(label_ + ": not a PLY file (its first line is not 'ply')");
    bool has_format = false;
    while (true) {
      const auto line = cursor_.next_line();
      if (!line) throw UserError(label_ + ": the header ends without 'end_header' (truncated file?)");
      LineTokens tokens(*line);
      const auto keyword = tokens.next();
      if (!keyword || *keyword == "comment" || *keyword == "obj_info") continue;
      if (*keyword == "end_header") break;
      if (*keyword == "format") {
        read_format(tokens);
        has_format = true;
      } else if (*keyword == "element") {
        read_element_line(tokens);
      } else if (*keyword == "property") {
        read_property_line(tokens);
      } else {
        header_error("unknown header line " + quoted(*line));
      }
    }
    if (!has_format) throw UserError(label_ + ": the header has no 'format' line");
  }

  static std::string_view trimmed(std::string_view text) {
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    return text;
  }

  [[noreturn]] void header_error(const std::string& problem) { throw_at_line(label_, cursor_.line_number(), problem); }

  void read_format(LineTokens& tokens) {
    const auto name = tokens.next();
    if (name == "ascii") {
      encoding_ = PlyEncoding::ascii;
    } else if (name == "binary_little_endian") {
      encoding_ = PlyEncoding::binary_little_endian;
    } else if (name == "binary_big_endian") {
      encoding_ = PlyEncoding::binary_big_endian;
    } else {
      header_error("unknown format " + quoted(name.value_or("")) +
                   " (expected ascii, binary_little_endian or binary_big_endian)");
    }
    swap_bytes_ = encoding_ == (std::endian::native == std::endian::little ? PlyEncoding::binary_big_endian
                                                                           : PlyEncoding::binary_little_endian);
  }

  void read_element_line(LineTokens& tokens) {
    const auto name = tokens.next();
    const auto count_token = tokens.next();
    const auto count = count_token ? parse_integer(*count_token) : std::nullopt;
    if (!name || !count_token) header_error("expected 'element NAME COUNT'");
    if (!count || *count < 0)
      header_error("the count of element " + quoted(*name) + ", " + quoted(*count_token) + ", is not a count");
    if ((*name == "vertex" || *name == "face" || *name == "tristrips") &&
        std::any_of(elements_.begin(), elements_.end(), [&](const PlyElement& e) { return e.name == *name; })) {
      header_error("a second '" + std::string(*name) + "' element");
    }
    elements_.push_back({std::string(*name), std::size_t(*count), {}});
  }

  void read_property_line(LineTokens& tokens) {
    if (elements_.empty()) header_error("a property before any element");
    PlyProperty property;
    auto type_name = tokens.next();
    if (type_name == "list") {
      const auto count_type_name = tokens.next();
      property.list_count_type = count_type_name ? parse_ply_type(*count_type_name) : std::nullopt;
      if (!property.list_count_type || !is_integer_type(*property.list_count_type)) {
        header_error("a list's count type must be an integer type, found " + quoted(count_type_name.value_or("")));
      }
      type_name = tokens.next();
    }
    const auto type = type_name ? parse_ply_type(*type_name) : std::nullopt;
    const auto name = tokens.next();
    if (!type || !name) header_error("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    property.type = *type;
    property.name = std::string(*name);
    elements_.back().properties.push_back(std::move(property));
  }

  // Each record's least size: a binary scalar or list count takes its bytes,
  // an ASCII one a digit and a separator; a list may be empty.
  std::size_t least_record_bytes(const PlyElement& element) const {
    std::size_t bytes = 0;
    for (const PlyProperty& p : element.properties) {
      bytes += encoding_ == PlyEncoding::ascii ? 2 : size_of(p.list_count_type.value_or(p.type));
    }
    return bytes;
  }

  void check_counts_fit() {
    const std::size_t left = cursor_.remaining() + (encoding_ == PlyEncoding::ascii ? 1 : 0);  // no final break needed
    std::size_t needed = 0;
    for (const PlyElement& element : elements_) {
      const std::size_t least = least_record_bytes(element);
      if (least > 0 && (element.count > left / least || needed + element.count * least > left)) {
        throw UserError(label_ + ": header declares " + std::to_string(element.count) + " " + quoted(element.name) +
                        " elements, more than the " + plural(cursor_.remaining(), "byte") +
                        " after it can hold (truncated file or corrupt header)");
      }
      needed += element.count * least;
    }
  }

  std::optional<std::size_t> find_property(const PlyElement& element, std::string_view name, bool list) const {
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      if (element.properties[k].name == name && element.properties[k].list_count_type.has_value() == list) return k;
    }
    return std::nullopt;
  }

  void read_element(const PlyElement& element) {
    if (element.properties.empty()) return;  // records of no bytes: nothing to read, however many
    element_ = &element;
    if (element.name == "vertex") {
      read_vertices(element);
    } else if (element.name == "face" || element.name == "tristrips") {
      read_index_lists(element);
    } else {
      for (record_ = 0; record_ < element.count; ++record_) {
        for (const PlyProperty& property : element.properties) read_property_past(property);
      }
    }
  }

  void read_vertices(const PlyElement& element) {
    std::array<std::size_t, 3> axis{};
    for (int k = 0; k < 3; ++k) {
      const std::string name(1, "xyz"[k]);
      const auto found = find_property(element, name, false);
      if (!found) throw UserError(label_ + ": the vertex element has no scalar property '" + name + "'");
      axis[k] = *found;
    }
    soup_.vertices.reserve(element.count);
    for (record_ = 0; record_ < element.count; ++record_) {
      Vec3 position;
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        if (property.list_count_type) {
          read_property_past(property);
          continue;
        }
        const double value = read_value(property.type);
        if (k == axis[0]) position.x = value;
        if (k == axis[1]) position.y = value;
        if (k == axis[2]) position.z = value;
      }
      soup_.vertices.push_back(position);
    }
  }

  void read_index_lists(const PlyElement& element) {
    const bool strips = element.name == "tristrips";
    auto indices = find_property(element, "vertex_indices", true);
    if (!indices && !strips) indices = find_property(element, "vertex_index", true);
    if (!indices) {
      throw UserError(label_ + ": the " + element.name + " element has no list property 'vertex_indices'");
    }
    if (!is_integer_type(element.properties[*indices].type)) {
      throw UserError(label_ + ": the " + element.name + " element's vertex indices are not of an integer type");
    }
    if (!strips) soup_.face_starts.reserve(element.count + 1);
    for (record_ = 0; record_ < element.count; ++record_) {
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        if (k != *indices) {
          read_property_past(element.properties[k]);
          continue;
        }
        read_list(element.properties[k], list_);
        if (strips) {
          add_strip_triangles(list_);
        } else {
          soup_.face_vertices.insert(soup_.face_vertices.end(), list_.begin(), list_.end());
          soup_.close_face();
        }
      }
    }
  }

  // Strip a b c d ...: triangles (a b c), (c b d), ... alternate in winding.
  void add_strip_triangles(const std::vector<long long>& strip) {
    std::size_t run = 0;
    long long a = 0, b = 0;
    for (const long long c : strip) {
      if (c == -1) {
        run = 0;
        continue;
      }
      if (run >= 2 && a != b && b != c && a != c) {
        if (run % 2 == 0) {
          soup_.add_triangle(a, b, c);
        } else {
          soup_.add_triangle(b, a, c);
        }
      }
      a = b;
      b = c;
      ++run;
    }
  }

  void read_list(const PlyProperty& property, std::vector<long long>& items) {
    items.clear();
    const std::size_t length = read_list_length(property);
    for (std::size_t k = 0; k < length; ++k) {  // each item takes at least a byte: ends with the file
      const auto index = as_whole_number(read_value(property.type));
      if (!index) record_error("a vertex index that is not a whole number");
      items.push_back(*index);
    }
  }

  std::size_t read_list_length(const PlyProperty& property) {
    const auto length = as_whole_number(read_value(*property.list_count_type));
    if (!length || *length < 0) record_error("a list length that is not a count");
    if (encoding_ != PlyEncoding::ascii && std::size_t(*length) > cursor_.remaining() / size_of(property.type)) {
      truncated();
    }
    return std::size_t(*length);
  }

  void read_property_past(const PlyProperty& property) {
    if (!property.list_count_type) {
      read_value(property.type);
      return;
    }
    const std::size_t length = read_list_length(property);
    if (encoding_ == PlyEncoding::ascii) {
      for (std::size_t k = 0; k < length; ++k) read_value(property.type);
    } else {
      cursor_.next_bytes(length * size_of(property.type));  // fits: read_list_length checked it
    }
  }

  double read_value(PlyType type) {
    if (encoding_ == PlyEncoding::ascii) {
      const auto token = cursor_.next_token();
      if (!token) truncated();
      const auto value = parse_real(*token);
      if (!value) throw_at_line(label_, cursor_.line_number(), "expected a number, found " + quoted(*token));
      return *value;
    }
    const auto bytes = cursor_.next_bytes(size_of(type));
    if (!bytes) truncated();
    return decode(type, bytes->data(), swap_bytes_);
  }

  [[noreturn]] void record_error(const std::string& problem) {
    const std::string where = record_name() + " has " + problem;
    if (encoding_ == PlyEncoding::ascii) throw_at_line(label_, cursor_.line_number(), where);
    throw UserError(label_ + ": " + where);
  }

  [[noreturn]] void truncated() {
    throw UserError(label_ + ": file ends inside " + record_name() + " of " + std::to_string(element_->count) +
                    " (truncated file?)");
  }

  // Names come from the file: quoted, so a message stays one short printable line.
  std::string record_name() const { return "element " + quoted(element_->name) + " record " + std::to_string(record_); }

  ByteCursor cursor_;
  const std::string& label_;
  PlyEncoding encoding_ = PlyEncoding::ascii;
  bool swap_bytes_ = false;
  std::vector<PlyElement> elements_;
  const PlyElement* element_ = nullptr;  // being read, for messages
  std::size_t record_ = 0;
  std::vector<long long> list_;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_ply(std::span<const char> bytes, const std::string& label) { return PlyReader(bytes, label).read(); }

}  // namespace meshparticles
