#pragma once
// One CSV field (RFC 4180): quoted when it holds a comma, a quote or a line
// break, with quotes doubled.
#include <string>

namespace meshparticles {

inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace meshparticles
