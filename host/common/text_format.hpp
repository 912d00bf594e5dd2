#pragma once
// Text the reports and messages share: numbers through a printf pattern, CSV
// fields, lists of choices.
#include <cstdio>
#include <string>
#include <vector>

#include "common/utf8_text.hpp"

namespace meshparticles {

// `value` through a printf pattern such as "%.3f".
inline std::string format_number(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// One CSV field (RFC 4180): quoted when it holds a comma, a quote or a line
// break, with quotes doubled.
inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// `text` on one line and valid UTF-8, whatever it quotes: a control
// character (a path may hold a newline) is written as an escape, \n, \r,
// \t or \xHH, and so is a byte that is not UTF-8 (common/utf8_text.hpp).
inline std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : escaped_utf8(text)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) line += c;
    else if (c == '\n') line += "\\n";
    else if (c == '\r') line += "\\r";
    else if (c == '\t') line += "\\t";
    else {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", unsigned(byte));
      line += escape;
    }
  }
  return line;
}

// "a, b or c" (or "a, b and c").
inline std::string choice_list(const std::vector<std::string>& names, const std::string& conjunction = "or") {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k) {
    text += (k == 0 ? "" : k + 1 == names.size() ? " " + conjunction + " " : ", ") + names[k];
  }
  return text;
}

}  // namespace meshparticles
