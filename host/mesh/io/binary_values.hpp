#pragma once
// Binary numbers as VTK files store them (legacy .vtk: big-endian; XML
// .vtp: either byte order): the ten scalar types, their sizes, and values
// read out of raw bytes as reals (coordinates) or exact integers (indices,
// block headers). One definition for both readers.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>

namespace meshparticles {

enum class ValueType { int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64 };

inline std::size_t size_of(ValueType type) {
  switch (type) {
    case ValueType::int8:
    case ValueType::uint8:
      return 1;
    case ValueType::int16:
    case ValueType::uint16:
      return 2;
    case ValueType::int32:
    case ValueType::uint32:
    case ValueType::float32:
      return 4;
    case ValueType::int64:
    case ValueType::uint64:
    case ValueType::float64:
      return 8;
  }
  return 0;
}

// Values of one type and byte order in `bytes` (a view: the bytes must outlive it).
class BinaryValues {
 public:
  BinaryValues(std::span<const unsigned char> bytes, ValueType type, bool big_endian)
      : bytes_(bytes), type_(type), big_endian_(big_endian) {}
  BinaryValues(const char* bytes, std::size_t count, ValueType type, bool big_endian)
      : BinaryValues({reinterpret_cast<const unsigned char*>(bytes), count * size_of(type)}, type, big_endian) {}

  std::size_t count() const { return bytes_.size() / size_of(type_); }

  double real(std::size_t i) const {
    switch (type_) {
      case ValueType::int8:
        return double(get<std::int8_t>(i));
      case ValueType::uint8:
        return double(get<std::uint8_t>(i));
      case ValueType::int16:
        return double(get<std::int16_t>(i));
      case ValueType::uint16:
        return double(get<std::uint16_t>(i));
      case ValueType::int32:
        return double(get<std::int32_t>(i));
      case ValueType::uint32:
        return double(get<std::uint32_t>(i));
      case ValueType::int64:
        return double(get<std::int64_t>(i));
      case ValueType::uint64:
        return double(get<std::uint64_t>(i));
      case ValueType::float32:
        return double(get<float>(i));
      case ValueType::float64:
        return get<double>(i);
    }
    return 0;
  }

  // An index or count; nothing for a real type or an unsigned value past
  // what long long holds.
  std::optional<long long> integer(std::size_t i) const {
    switch (type_) {
      case ValueType::float32:
      case ValueType::float64:
        return std::nullopt;
      case ValueType::uint64: {
        const std::uint64_t value = get<std::uint64_t>(i);
        if (value > std::uint64_t(INT64_MAX)) return std::nullopt;
        return static_cast<long long>(value);
      }
      case ValueType::int64:
        return get<std::int64_t>(i);
      default:
        return static_cast<long long>(real(i));
    }
  }

  // A .vtp block header's byte count (UInt32 or UInt64), exact: through a
  // double a count near 2^64 would not convert back.
  std::uint64_t header_count(std::size_t i) const {
    return type_ == ValueType::uint64 ? get<std::uint64_t>(i) : std::uint64_t(get<std::uint32_t>(i));
  }

 private:
  template <typename T>
  T get(std::size_t i) const {
    std::array<unsigned char, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes_.data() + i * sizeof(T), sizeof(T));
    if (big_endian_ != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
    return std::bit_cast<T>(raw);
  }

  std::span<const unsigned char> bytes_;
  ValueType type_;
  bool big_endian_;
};

}  // namespace meshparticles
