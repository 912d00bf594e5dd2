// Wavefront OBJ, the polygonal part: 'v x y z [w]' (colours some writers put
// after x y z are ignored) and 'f' with entries v, v/vt, v//vn or v/vt/vn;
// indices count from 1, negative ones back from the last vertex read so far.
// '#' starts a comment, a line ending in '\' continues on the next, and the
// other statements of the format (vt, vn, o, g, s, usemtl, mtllib, l, p,
// free-form geometry, ...) are read past. Any other statement is refused:
// it means this is not the file it claims to be.
#include <array>
#include <string>

#include "common/user_error.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"

namespace meshparticles {

namespace {

bool is_known_statement(std::string_view keyword) {
  static constexpr std::string_view kIgnored[] = {
      // texture and normal data, points and lines
      "vt", "vn", "vp", "p", "l",
      // grouping and display
      "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "lod", "bevel", "c_interp", "d_interp", "shadow_obj",
      "trace_obj", "ctech", "stech",
      // free-form curves and surfaces
      "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con",
      // other files and commands
      "call", "csh"};
  for (const std::string_view known : kIgnored) {
    if (keyword == known) return true;
  }
  return false;
}

class ObjReader {
 public:
  ObjReader(std::span<const char> bytes, const std::string& label) : cursor_(bytes), label_(label) {}

  PolygonSoup read() {
    cursor_.skip_byte_order_mark();
    while (const auto line = next_statement()) {
      LineTokens tokens(*line);
      const auto keyword = tokens.next();
      if (!keyword) continue;
      if (*keyword == "v") {
        read_vertex(tokens);
      } else if (*keyword == "f") {
        read_face(tokens);
      } else if (!is_known_statement(*keyword)) {
        fail("unknown statement " + quoted(*keyword));
      }
    }
    return std::move(soup_);
  }

 private:
  // The next logical line, comment removed, continuation lines joined.
  std::optional<std::string_view> next_statement() {
    const auto line = cursor_.next_line();
    if (!line) return std::nullopt;
    statement_line_ = cursor_.line_number();
    std::string_view content = line->substr(0, line->find('#'));
    if (!continues(content)) return content;
    joined_.assign(content.substr(0, content.size() - 1));
    while (true) {
      const auto next = cursor_.next_line();
      if (!next) break;
      content = next->substr(0, next->find('#'));
      const bool more = continues(content);
      joined_ += ' ';
      joined_.append(more ? content.substr(0, content.size() - 1) : content);
      if (!more) break;
    }
    return std::string_view(joined_);
  }
  static bool continues(std::string_view content) { return !content.empty() && content.back() == '\\'; }

  [[noreturn]] void fail(const std::string& problem) { throw_at_line(label_, statement_line_, problem); }

  void read_vertex(LineTokens& tokens) {
    std::array<double, 3> position{};
    for (double& coordinate : position) {
      const auto token = tokens.next();
      const auto value = token ? parse_real(*token) : std::nullopt;
      if (!value) fail("expected a coordinate, found " + (token ? quoted(*token) : std::string("the end of the line")));
      coordinate = *value;
    }
    soup_.vertices.push_back({position[0], position[1], position[2]});
  }

  void read_face(LineTokens& tokens) {
    while (const auto entry = tokens.next()) {
      const std::string_view vertex = entry->substr(0, entry->find('/'));
      const auto index = parse_integer(vertex);
      if (!index || *index == 0) fail("expected a vertex index (from 1, or negative), found " + quoted(*entry));
      const auto read_so_far = static_cast<long long>(soup_.vertices.size());
      if (*index < -read_so_far) {
        fail("relative index " + std::to_string(*index) + " reaches before the first vertex (" +
             std::to_string(read_so_far) + " read so far)");
      }
      soup_.face_vertices.push_back(*index > 0 ? *index - 1 : read_so_far + *index);
    }
    soup_.close_face();
  }

  ByteCursor cursor_;
  const std::string& label_;
  std::size_t statement_line_ = 0;
  std::string joined_;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_obj(std::span<const char> bytes, const std::string& label) { return ObjReader(bytes, label).read(); }

}  // namespace meshparticles
