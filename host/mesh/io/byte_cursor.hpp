#pragma once
// A bounded read position in a mesh file held in memory, shared by the format
// readers. Every read checks the bytes left, so no read loop can outlive the
// file, and text reads count lines so errors can name one.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace meshparticles {

class ByteCursor {
 public:
  explicit ByteCursor(std::span<const char> bytes) : bytes_(bytes) {}

  // Skips a UTF-8 byte order mark at the start: Windows editors write one
  // before text that is otherwise plain ASCII.
  void skip_byte_order_mark();

  std::size_t remaining() const { return bytes_.size() - position_; }
  bool at_end() const { return position_ == bytes_.size(); }
  // The line (1-based) of what the last next_line or next_token returned.
  std::size_t line_number() const { return line_number_; }

  // The next line without its line break ("\n", "\r\n" or a lone "\r");
  // nothing at the end of the input.
  std::optional<std::string_view> next_line();
  // The next run of non-whitespace bytes, across line breaks; nothing when
  // only whitespace is left.
  std::optional<std::string_view> next_token();
  // The next `count` raw bytes; nothing (and no move) when fewer are left.
  std::optional<std::span<const char>> next_bytes(std::size_t count);

 private:
  std::span<const char> bytes_;
  std::size_t position_ = 0;
  std::size_t line_breaks_passed_ = 0;
  std::size_t line_number_ = 0;
};

// The whitespace-separated tokens of one line.
class LineTokens {
 public:
  explicit LineTokens(std::string_view line) : rest_(line) {}
  std::optional<std::string_view> next();

 private:
  std::string_view rest_;
};

bool is_space(char c);

// A whole token as a number, or nothing. A leading '+' is allowed (printf
// writes it with %+g, and strtod reads it; std::from_chars alone does not).
// "nan" and "inf" parse: the mesh checks refuse them with a clearer message.
std::optional<double> parse_real(std::string_view token);
std::optional<long long> parse_integer(std::string_view token);

// A token or line from the file for an error message: at most 40 bytes, in
// quotes, anything unprintable as '?', so a message stays one printable line.
std::string quoted(std::string_view text);

// UserError("LABEL: line N: PROBLEM").
[[noreturn]] void throw_at_line(const std::string& label, std::size_t line, const std::string& problem);

}  // namespace meshparticles
