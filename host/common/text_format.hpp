#pragma once
// Text the reports share: numbers through a printf pattern, and CSV fields.
#include <cstdio>
#include <string>

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

}  // namespace meshparticles
