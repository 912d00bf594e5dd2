#include "options/number_options.hpp"

#include <charconv>
#include <cmath>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// Quoted, and cut short: the message stays one readable line whatever was typed.
std::string quoted(const std::string& text) {
  constexpr std::size_t kShown = 40;
  return "\"" + (text.size() > kShown ? text.substr(0, kShown) + "..." : text) + "\"";
}

}  // namespace

std::string option_label(const std::string& names) {
  std::string label = names;
  for (char& c : label) {
    if (c == ',') c = '/';
  }
  return label;
}

std::uint64_t parse_whole_number(const std::string& text, const std::string& option, WholeRange range) {
  std::uint64_t value = 0;
  // from_chars takes no sign, no base prefix and no spaces; the digits
  // must be the whole text, and a value past 2^64 - 1 is refused, not wrapped.
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value, 10);
  const bool digits_only = !text.empty() && stop == end && error == std::errc{};
  if (!digits_only || value < range.min || value > range.max) {
    throw UserError(whole_number_refusal(option, range, quoted(text)));
  }
  return value;
}

double parse_positive_number(const std::string& text, const std::string& option) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || stop != end || error != std::errc{} || !is_positive_number(value)) {
    throw UserError(positive_number_refusal(option, quoted(text)));
  }
  return value;
}

bool is_positive_number(double value) { return std::isfinite(value) && value > 0; }

std::string whole_number_refusal(const std::string& option, WholeRange range, const std::string& given) {
  return option + ": expected a whole number from " + std::to_string(range.min) + " to " + std::to_string(range.max) +
         ", got " + given;
}

std::string positive_number_refusal(const std::string& option, const std::string& given) {
  return option + ": expected a finite number above 0, got " + given;
}

CLI::Option* add_positive_number_option(CLI::App& command, const std::string& names, std::optional<double>& target,
                                        const std::string& help) {
  const std::string label = option_label(names);
  CLI::Option* option = command.add_option_function<std::string>(
      names, [&target, label](const std::string& text) { target = parse_positive_number(text, label); }, help);
  option->type_name("NUMBER");
  return option;
}

}  // namespace meshparticles
