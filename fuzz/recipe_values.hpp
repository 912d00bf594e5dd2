#pragma once
// Numbers as the recipe writers put them in a file: text, or binary of a
// given type and byte order (wrapping, as a careless writer's cast would).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace meshparticles::fuzzing {

enum class Kind { int32, int64, uint32, uint64, float32, float64 };

// The index types a recipe chooses among (Recipe::index_type).
inline Kind index_kind(std::uint8_t index_type) {
  static constexpr Kind kKinds[] = {Kind::int32, Kind::int64, Kind::uint32, Kind::uint64};
  return kKinds[index_type % 4];
}

template <typename T>
void append_raw(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

inline void append_binary(std::string& out, Kind kind, double real, long long integer, bool big_endian) {
  switch (kind) {
    case Kind::int32: return append_raw(out, std::int32_t(integer), big_endian);
    case Kind::int64: return append_raw(out, std::int64_t(integer), big_endian);
    case Kind::uint32: return append_raw(out, std::uint32_t(integer), big_endian);
    case Kind::uint64: return append_raw(out, std::uint64_t(integer), big_endian);
    case Kind::float32: return append_raw(out, float(real), big_endian);
    case Kind::float64: return append_raw(out, real, big_endian);
  }
}

inline std::string real_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace meshparticles::fuzzing
