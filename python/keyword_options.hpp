#pragma once
// Keyword arguments taken one by one by name, the way the command line takes
// its options: each read once with its type (python/argument_values.hpp),
// None meaning absent, and any left over refused by name (a misspelt option
// must not be ignored).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "argument_values.hpp"

namespace meshparticles::python {

class KeywordOptions {
 public:
  explicit KeywordOptions(const pybind11::kwargs& given) : left_(pybind11::dict(given)) {}

  // Whether `name` is given, and not None, among those not yet taken.
  bool given(const char* name) const { return left_.contains(name) && !left_[name].is_none(); }

  // The value of `name` as it is, or nothing when absent or None.
  std::optional<pybind11::object> take_object(const char* name) {
    if (!left_.contains(name)) return std::nullopt;
    pybind11::object value = left_.attr("pop")(name);
    if (value.is_none()) return std::nullopt;
    return value;
  }

  // A whole number within `range` (the command line's, options/number_options.hpp),
  // refused in its words: "iterations: expected a whole number from 0 to 1000000, got -1".
  std::optional<std::uint64_t> take_whole(const char* name, WholeRange range) {
    return taken(name, [&](pybind11::handle value) { return whole_number(value, name, range); });
  }
  // A finite number above 0: "sigma: expected a finite number above 0, got inf".
  std::optional<double> take_positive(const char* name) {
    return taken(name, [&](pybind11::handle value) { return positive_number(value, name); });
  }
  std::optional<bool> take_flag(const char* name) {
    return taken(name, [&](pybind11::handle value) { return flag(value, name); });
  }
  std::optional<std::string> take_word(const char* name) {
    return taken(name, [&](pybind11::handle value) { return word(value, name); });
  }
  std::optional<std::filesystem::path> take_path(const char* name) {
    return taken(name, [&](pybind11::handle value) { return path_argument(value, name); });
  }

  // Throws TypeError naming the first keyword nothing took.
  void refuse_unknown(const std::string& function) const {
    for (const auto& item : left_) {
      throw pybind11::type_error(function + "() got an unexpected keyword argument '" +
                                 pybind11::str(item.first).cast<std::string>() + "'");
    }
  }

 private:
  template <typename Convert>
  auto taken(const char* name, Convert convert) -> std::optional<decltype(convert(pybind11::handle()))> {
    const auto value = take_object(name);
    if (!value) return std::nullopt;
    return convert(*value);
  }

  pybind11::dict left_;
};

}  // namespace meshparticles::python
