#pragma once
// Numbers as the recipe writers put them in a file: text, or binary of a
// given type and byte order (wrapping, as a careless writer's cast would).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "mesh/io/binary_values.hpp"

namespace meshparticles::fuzzing {

// The index types a recipe chooses among (Recipe::index_type).
inline ValueType index_type_of(std::uint8_t index_type) {
  static constexpr ValueType kTypes[] = {ValueType::int32, ValueType::int64, ValueType::uint32, ValueType::uint64};
  return kTypes[index_type % 4];
}

template <typename T>
void append_raw(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

// A value of `type`: `real` for the two real types, `integer` for the others.
inline void append_binary(std::string& out, ValueType type, double real, long long integer, bool big_endian) {
  switch (type) {
    case ValueType::int8: return append_raw(out, std::int8_t(integer), big_endian);
    case ValueType::uint8: return append_raw(out, std::uint8_t(integer), big_endian);
    case ValueType::int16: return append_raw(out, std::int16_t(integer), big_endian);
    case ValueType::uint16: return append_raw(out, std::uint16_t(integer), big_endian);
    case ValueType::int32: return append_raw(out, std::int32_t(integer), big_endian);
    case ValueType::int64: return append_raw(out, std::int64_t(integer), big_endian);
    case ValueType::uint32: return append_raw(out, std::uint32_t(integer), big_endian);
    case ValueType::uint64: return append_raw(out, std::uint64_t(integer), big_endian);
    case ValueType::float32: return append_raw(out, float(real), big_endian);
    case ValueType::float64: return append_raw(out, real, big_endian);
  }
}

inline std::string real_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace meshparticles::fuzzing
