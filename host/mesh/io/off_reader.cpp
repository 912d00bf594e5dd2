// OFF as Geomview defines it:
//   [ST][C][N][4][n]OFF          keyword, optional
//   [Ndim]                       with n only
//   Nvertices Nfaces [Nedges]
//   x y z [more numbers]         one vertex per line
//   k i_1 ... i_k [colour]       one face per line, any k
// '#' starts a comment anywhere in a line; blank lines are ignored. A vertex
// line's numbers after its position (normal, colour, texture coordinates,
// per the prefixes) and a face line's colour after its indices are ignored.
// 4OFF vertices are homogeneous (x y z w, read as x/w y/w z/w); nOFF must
// have Ndim 3. "OFF BINARY" is refused: no mesh tool we know writes it.
#include <optional>
#include <vector>

#include "common/user_error.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

struct OffKeyword {
  bool homogeneous = false;         // 4: a fourth coordinate w divides the others
  bool declares_dimension = false;  // n: Ndim follows the keyword
};

std::optional<OffKeyword> parse_keyword(std::string_view word) {
  if (!word.ends_with("OFF")) return std::nullopt;
  word.remove_suffix(3);
  for (const std::string_view prefix : {"ST", "C", "N"}) {
    if (word.starts_with(prefix)) word.remove_prefix(prefix.size());
  }
  OffKeyword keyword;
  if (word.starts_with('4')) {
    keyword.homogeneous = true;
    word.remove_prefix(1);
  }
  if (word.starts_with('n')) {
    keyword.declares_dimension = true;
    word.remove_prefix(1);
  }
  if (!word.empty()) return std::nullopt;
  return keyword;
}

// The next line with something on it, its comment removed.
std::optional<std::string_view> next_content_line(ByteCursor& cursor) {
  while (const auto line = cursor.next_line()) {
    const std::string_view content = line->substr(0, line->find('#'));
    for (const char c : content) {
      if (!is_space(c)) return content;
    }
  }
  return std::nullopt;
}

std::vector<std::string_view> remaining_tokens(LineTokens& tokens) {
  std::vector<std::string_view> result;
  while (const auto token = tokens.next()) result.push_back(*token);
  return result;
}

class OffReader {
 public:
  OffReader(std::span<const char> bytes, const std::string& label) : cursor_(bytes), label_(label) {}

  PolygonSoup read() {
    const std::vector<std::string_view> counts = read_header();
    const std::size_t vertex_count = parse_count(counts[0], "vertex");
    const std::size_t face_count = parse_count(counts[1], "face");
    check_counts_fit(vertex_count, face_count);
    soup_.vertices.reserve(vertex_count);
    soup_.face_starts.reserve(face_count + 1);
    for (std::size_t v = 0; v < vertex_count; ++v) read_vertex(v, vertex_count);
    for (std::size_t f = 0; f < face_count; ++f) read_face(f, face_count);
    warn_of_content_after_faces(face_count);
    return std::move(soup_);
  }

 private:
  // Reads the keyword (if any) and Ndim; returns the count tokens.
  std::vector<std::string_view> read_header() {
    cursor_.skip_byte_order_mark();
    auto line = next_content_line(cursor_);
    if (!line) throw UserError(label_ + ": empty file (no OFF header)");
    LineTokens tokens(*line);
    const std::string_view first = *tokens.next();
    if (parse_integer(first)) return checked_counts(*line);  // the keyword is optional
    const auto keyword = parse_keyword(first);
    if (!keyword) {
      throw_at_line(
          label_, cursor_.line_number(),
          "expected an OFF keyword ([ST][C][N][4][n]OFF) or the vertex and face counts, found " + quoted(first));
    }
    homogeneous_ = keyword->homogeneous;
    std::vector<std::string_view> rest = remaining_tokens(tokens);
    if (!rest.empty() && rest[0] == "BINARY") {
      throw UserError(label_ + ": binary OFF is not supported (convert it to ASCII OFF or to PLY)");
    }
    if (keyword->declares_dimension) {
      if (rest.empty()) rest = tokens_of_next_line("the dimension nOFF declares");
      const auto dimension = parse_integer(rest[0]);
      if (dimension != 3) {
        throw_at_line(label_, cursor_.line_number(),
                      "nOFF dimension " + quoted(rest[0]) + ": only 3-dimensional vertices are supported");
      }
      rest.erase(rest.begin());
    }
    if (rest.empty()) rest = tokens_of_next_line("the vertex and face counts");
    return checked_counts(rest);
  }

  std::vector<std::string_view> tokens_of_next_line(const std::string& what) {
    const auto line = next_content_line(cursor_);
    if (!line) throw UserError(label_ + ": file ends before " + what);
    LineTokens tokens(*line);
    return remaining_tokens(tokens);
  }

  std::vector<std::string_view> checked_counts(std::string_view line) {
    LineTokens tokens(line);
    return checked_counts(remaining_tokens(tokens));
  }
  std::vector<std::string_view> checked_counts(std::vector<std::string_view> counts) {
    if (counts.size() != 2 && counts.size() != 3) {
      std::string found;
      for (const std::string_view token : counts) {
        if (!found.empty()) found += ' ';
        found += token;
      }
      throw_at_line(label_, cursor_.line_number(), "expected 'Nvertices Nfaces [Nedges]', found " + quoted(found));
    }
    return counts;
  }

  std::size_t parse_count(std::string_view token, const std::string& what) {
    const auto count = parse_integer(token);
    if (!count || *count < 0) {
      throw_at_line(label_, cursor_.line_number(), "the " + what + " count " + quoted(token) + " is not a count");
    }
    return std::size_t(*count);
  }

  // Before anything is allocated: a vertex line takes at least two bytes per
  // coordinate ("0 0 0\n"), a face line at least two ("0\n").
  void check_counts_fit(std::size_t vertex_count, std::size_t face_count) {
    const std::size_t left = cursor_.remaining();
    const std::size_t coordinates = homogeneous_ ? 4 : 3;
    if (vertex_count > left || face_count > left ||
        vertex_count * 2 * coordinates + face_count * 2 > left + 1) {  // the last line may lack its break
      throw UserError(label_ + ": header declares " + plural(vertex_count, "vertex", "vertices") + " and " +
                      plural(face_count, "face") + ", more than the " + plural(left, "byte") +
                      " after it can hold (truncated file or corrupt header)");
    }
  }

  void read_vertex(std::size_t v, std::size_t vertex_count) {
    const auto line = next_content_line(cursor_);
    if (!line) {
      throw UserError(label_ + ": file ends after " + std::to_string(v) + " of the " +
                      plural(vertex_count, "vertex", "vertices") + " the header declares (truncated file?)");
    }
    LineTokens tokens(*line);
    double coordinate[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < (homogeneous_ ? 4u : 3u); ++k) {
      const auto token = tokens.next();
      const auto value = token ? parse_real(*token) : std::nullopt;
      if (!value) {
        throw_at_line(label_, cursor_.line_number(),
                      "vertex " + std::to_string(v) + ": expected a coordinate, found " +
                          (token ? quoted(*token) : std::string("the end of the line")));
      }
      coordinate[k] = *value;
    }
    const double w = coordinate[3];
    soup_.vertices.push_back({coordinate[0] / w, coordinate[1] / w, coordinate[2] / w});
  }

  void read_face(std::size_t f, std::size_t face_count) {
    const auto line = next_content_line(cursor_);
    if (!line) {
      throw UserError(label_ + ": file ends after " + std::to_string(f) + " of the " + plural(face_count, "face") +
                      " the header declares (truncated file?)");
    }
    const std::string where = "face " + std::to_string(f);
    LineTokens tokens(*line);
    const std::string_view size_token = *tokens.next();
    const auto size = parse_integer(size_token);
    if (!size || *size < 0) {
      throw_at_line(label_, cursor_.line_number(),
                    where + ": expected its number of vertices, found " + quoted(size_token));
    }
    if (*size < 3) {  // often a vertex line beyond the count the header gives
      throw_at_line(
          label_, cursor_.line_number(),
          where + " declares " + plural(std::size_t(*size), "vertex", "vertices") + ", fewer than a face needs");
    }
    for (long long k = 0; k < *size; ++k) {  // ends with the line: each index is a token
      const auto token = tokens.next();
      if (!token) {
        throw_at_line(label_, cursor_.line_number(),
                      where + " lists " + std::to_string(k) + " of the " +
                          plural(std::size_t(*size), "vertex", "vertices") + " it declares");
      }
      const auto index = parse_integer(*token);
      if (!index)
        throw_at_line(label_, cursor_.line_number(), where + ": expected a vertex index, found " + quoted(*token));
      soup_.face_vertices.push_back(*index);
    }
    soup_.close_face();
  }

  // Geomview reads what the header declares and stops; so do we, but say so.
  void warn_of_content_after_faces(std::size_t face_count) {
    if (!next_content_line(cursor_)) return;
    const std::size_t first = cursor_.line_number();
    std::size_t lines = 1;
    while (next_content_line(cursor_)) ++lines;
    soup_.warnings.push_back(label_ + ": " + plural(lines, "line") + " after the " + plural(face_count, "face") +
                             " the header declares (from line " + std::to_string(first) + ") ignored");
  }

  ByteCursor cursor_;
  const std::string& label_;
  bool homogeneous_ = false;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_off(std::span<const char> bytes, const std::string& label) { return OffReader(bytes, label).read(); }

}  // namespace meshparticles
