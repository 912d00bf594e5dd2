#pragma once
// Keyword arguments taken one by one by name, the way the command line takes
// its options: each read once with its type, None meaning absent, and any
// left over refused by name (a misspelt option must not be ignored).
#include <cstdint>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "cli/number_options.hpp"

namespace meshparticles::python {

class KeywordOptions {
 public:
  explicit KeywordOptions(const pybind11::kwargs& given) : left_(pybind11::dict(given)) {}

  // Whether `name` is given, and not None, among those not yet taken.
  bool given(const char* name) const { return left_.contains(name) && !left_[name].is_none(); }

  // The value of `name` as T, or nothing when absent or None. Throws
  // TypeError naming the keyword when it is not a T.
  template <typename T>
  std::optional<T> take(const char* name) {
    if (!left_.contains(name)) return std::nullopt;
    const pybind11::object value = left_.attr("pop")(name);
    if (value.is_none()) return std::nullopt;
    try {
      return value.cast<T>();
    } catch (const pybind11::cast_error&) {
      throw pybind11::type_error(std::string(name) + ": " + describe_expected<T>() + " expected, got " +
                                 pybind11::str(pybind11::type::of(value)).cast<std::string>());
    }
  }

  // A whole number within `range` (the command line's, cli/number_options.hpp),
  // refused in its words: "iterations: expected a whole number from 0 to 1000000, got -1".
  std::optional<std::uint64_t> take_whole(const char* name, WholeRange range) {
    const auto value = take<pybind11::int_>(name);
    if (!value) return std::nullopt;
    const bool in_range = *value >= pybind11::int_(range.min) && *value <= pybind11::int_(range.max);
    if (!in_range) {
      throw pybind11::value_error(std::string(name) + ": expected a whole number from " + std::to_string(range.min) +
                                  " to " + std::to_string(range.max) + ", got " +
                                  pybind11::str(pybind11::handle(*value)).cast<std::string>());
    }
    return value->cast<std::uint64_t>();
  }

  // Throws TypeError naming the first keyword nothing took.
  void refuse_unknown(const std::string& function) const {
    for (const auto& item : left_) {
      throw pybind11::type_error(function + "() got an unexpected keyword argument '" +
                                 pybind11::str(item.first).cast<std::string>() + "'");
    }
  }

 private:
  template <typename T>
  static const char* describe_expected() {
    if constexpr (std::is_same_v<T, bool>) return "True or False";
    else if constexpr (std::is_same_v<T, pybind11::int_>) return "an integer";
    else if constexpr (std::is_integral_v<T>) return "an integer";
    else if constexpr (std::is_floating_point_v<T>) return "a number";
    else return "a string";
  }

  pybind11::dict left_;
};

}  // namespace meshparticles::python
