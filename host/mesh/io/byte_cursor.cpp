#include "mesh/io/byte_cursor.hpp"

#include <charconv>

#include "common/user_error.hpp"

namespace meshparticles {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

void ByteCursor::skip_byte_order_mark() {
  if (position_ == 0 && std::string_view(bytes_.data(), bytes_.size()).starts_with("\xEF\xBB\xBF")) position_ = 3;
}

std::optional<std::string_view> ByteCursor::next_line() {
  if (at_end()) return std::nullopt;
  const std::size_t start = position_;
  while (position_ < bytes_.size() && bytes_[position_] != '\n' && bytes_[position_] != '\r') ++position_;
  const std::string_view line(bytes_.data() + start, position_ - start);
  if (position_ < bytes_.size()) {
    if (bytes_[position_] == '\r' && position_ + 1 < bytes_.size() && bytes_[position_ + 1] == '\n') ++position_;
    ++position_;
  }
  line_number_ = ++line_breaks_passed_;  // a last line without a break still counts as one
  return line;
}

std::optional<std::string_view> ByteCursor::next_token() {
  while (position_ < bytes_.size() && is_space(bytes_[position_])) {
    const char c = bytes_[position_++];
    // "\r\n" is one line break: count it at its '\n'.
    if (c == '\n' || (c == '\r' && (position_ == bytes_.size() || bytes_[position_] != '\n'))) ++line_breaks_passed_;
  }
  if (at_end()) return std::nullopt;
  const std::size_t start = position_;
  while (position_ < bytes_.size() && !is_space(bytes_[position_])) ++position_;
  line_number_ = line_breaks_passed_ + 1;
  return std::string_view(bytes_.data() + start, position_ - start);
}

std::optional<std::span<const char>> ByteCursor::next_bytes(std::size_t count) {
  if (count > remaining()) return std::nullopt;
  const std::span<const char> result = bytes_.subspan(position_, count);
  position_ += count;
  return result;
}

std::optional<std::string_view> LineTokens::next() {
  std::size_t start = 0;
  while (start < rest_.size() && is_space(rest_[start])) ++start;
  if (start == rest_.size()) return std::nullopt;
  std::size_t end = start;
  while (end < rest_.size() && !is_space(rest_[end])) ++end;
  const std::string_view token = rest_.substr(start, end - start);
  rest_.remove_prefix(end);
  return token;
}

namespace {

template <typename Number>
std::optional<Number> parse_whole(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  Number value{};
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<double> parse_real(std::string_view token) { return parse_whole<double>(token); }
std::optional<long long> parse_integer(std::string_view token) { return parse_whole<long long>(token); }

std::string quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;
  std::string result = "'";
  for (char c : text.substr(0, kShown)) result += (c >= 0x20 && c < 0x7f) ? c : '?';
  return result + (text.size() > kShown ? "...'" : "'");
}

void throw_at_line(const std::string& label, std::size_t line, const std::string& problem) {
  throw UserError(label + ": line " + std::to_string(line) + ": " + problem);
}

}  // namespace meshparticles
