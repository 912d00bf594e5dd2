#pragma once
// Numeric options, parsed strictly. CLI11 reads unsigned options with base 0
// and wraps negatives ("-1" becomes 2^64 - 1, "010" is 8, "0x3" is 3) and
// lets NaN through for doubles; every numeric option of every command goes
// through these functions instead: decimal digits only, the whole text,
// range-checked before use, with the option and its range named in words:
//   --iterations: expected a whole number from 0 to 1000000, got "-1"
#include <CLI/CLI.hpp>
#include "options/option_values.hpp"
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace meshparticles {

struct WholeRange {
  std::uint64_t min = 0;
  std::uint64_t max = 0;
};

// The ranges several commands share, and why.
// Particle counts and input vertex ids: vertices are numbered in 32 bits;
// n <= V and the vertex's existence are checked against the mesh later.
inline constexpr WholeRange kParticleRange{1, std::numeric_limits<std::uint32_t>::max()};
inline constexpr WholeRange kVertexIdRange{0, std::numeric_limits<std::uint32_t>::max()};
// Colour groups: K >= n already gives every particle its own group, and the
// serial backends make K passes per iteration, so a huge K would only hang them.
inline constexpr WholeRange kColorRange{1, 4096};
// Kernel sizes: the device's own limits are checked once it is known; these
// bounds only keep the numbers (and their products) sane.
inline constexpr WholeRange kWorkGroupRange{1, std::uint64_t{1} << 20};
inline constexpr WholeRange kTileRange{1, std::uint64_t{1} << 24};
// A run stops by itself when nothing moves; a million iterations is days on
// any mesh worth running, so more is a typing error.
inline constexpr WholeRange kRunIterationRange{0, 1000000};
inline constexpr WholeRange kRelaxRoundRange{0, 1000000};
// Timed iterations of sweep and bench: at least one; the paper timed 1000.
inline constexpr WholeRange kTimedIterationRange{1, 100000};
inline constexpr WholeRange kRebuildRange{0, 1000000};
inline constexpr WholeRange kThreadRange{0, 1024};
inline constexpr WholeRange kSeedRange{0, std::numeric_limits<std::uint64_t>::max()};
// Generated meshes: from the smallest sphere to what 32-bit vertex ids and
// this machine's memory allow to build.
inline constexpr WholeRange kLargeMeshRange{12, 100000000};
// generate --population: up to 100,000 shapes.
inline constexpr WholeRange kPopulationRange{1, 100000};

// `text` as a decimal whole number within `range`; throws UserError naming
// `option` otherwise.
std::uint64_t parse_whole_number(const std::string& text, const std::string& option, WholeRange range);

// `text` as a finite number above zero; throws UserError naming `option` otherwise.
double parse_positive_number(const std::string& text, const std::string& option);

// What a positive-number option takes: finite and above 0.
bool is_positive_number(double value);

// The refusals, in the words the command line and the Python module share
// ("OPTION: expected a finite number above 0, got GIVEN").
std::string whole_number_refusal(const std::string& option, WholeRange range, const std::string& given);
std::string positive_number_refusal(const std::string& option, const std::string& given);

// "-n/--particles" for the names "-n,--particles": how messages name an option.
std::string option_label(const std::string& names);

namespace detail {
template <typename T>
struct NumberTarget {
  using value_type = T;
};
template <typename T>
struct NumberTarget<std::optional<T>> {
  using value_type = T;
};
}  // namespace detail

// A whole-number option stored in `target` (an unsigned integer or an
// optional one). The range goes into --help; a non-optional target's value
// is shown as the default.
template <typename Target>
CLI::Option* add_whole_number_option(CLI::App& command, const std::string& names, Target& target, WholeRange range,
                                     const std::string& help) {
  using Value = typename detail::NumberTarget<Target>::value_type;
  static_assert(std::is_unsigned_v<Value>);
  if (range.max > std::numeric_limits<Value>::max()) throw std::logic_error(names + ": range wider than its type");
  const std::string label = option_label(names);
  CLI::Option* option = command.add_option_function<std::string>(
      names, [&target, label, range](const std::string& text) { target = Value(parse_whole_number(text, label, range)); },
      help + " [" + std::to_string(range.min) + ".." + std::to_string(range.max) + "]");
  option->type_name("UINT");
  if constexpr (std::is_same_v<Target, Value>) option->default_str(std::to_string(target));
  return option;
}

// A comma-separated list of whole numbers, each within `range`; the list
// given replaces the default shown.
template <typename Value>
CLI::Option* add_whole_number_list_option(CLI::App& command, const std::string& names, std::vector<Value>& target,
                                          WholeRange range, const std::string& help) {
  static_assert(std::is_unsigned_v<Value>);
  if (range.max > std::numeric_limits<Value>::max()) throw std::logic_error(names + ": range wider than its type");
  const std::string label = option_label(names);
  std::string defaults;
  for (const Value value : target) defaults += (defaults.empty() ? "" : ",") + std::to_string(value);
  CLI::Option* option = command.add_option_function<std::vector<std::string>>(
      names,
      [&target, label, range](const std::vector<std::string>& texts) {
        target.clear();
        for (const std::string& list : texts) {
          for (const std::string& text : split_list(list, label)) {
            target.push_back(Value(parse_whole_number(text, label, range)));
          }
        }
      },
      help + " [each " + std::to_string(range.min) + ".." + std::to_string(range.max) + "]");
  option->type_name("UINT,...")->allow_extra_args(false)->default_str(defaults);
  return option;
}

// A number above zero and finite (NaN and infinities are refused).
CLI::Option* add_positive_number_option(CLI::App& command, const std::string& names, std::optional<double>& target,
                                        const std::string& help);

}  // namespace meshparticles
