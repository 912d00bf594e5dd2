#pragma once
// Numbers as text that reads back to the same double: the shortest decimal
// form that does (std::to_chars), for the coordinates a user reads back
// (particle files, CSV, PLY, VTK). Nine significant digits put a unit
// sphere at x = 1e7 on steps of 0.1, and `quality` of such a file measured
// other particles than the run's.
#include <charconv>
#include <string>

namespace meshparticles {

// Appends `value` in its shortest round-trip form ("0.1", "1e+07", "-0").
inline void append_exact(std::string& text, double value) {
  char digits[32];  // the longest form, "-2.2250738585072014e-308", takes 24
  text.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

// Appends "x y z" (`separator` between), each exact.
inline void append_exact_triple(std::string& text, double x, double y, double z, char separator = ' ') {
  append_exact(text, x);
  text += separator;
  append_exact(text, y);
  text += separator;
  append_exact(text, z);
}

// "x y z" (`separator` between), each exact.
inline std::string exact_triple(double x, double y, double z, char separator = ' ') {
  std::string text;
  append_exact_triple(text, x, y, z, separator);
  return text;
}

}  // namespace meshparticles
