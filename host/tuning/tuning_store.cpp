#include "tuning/tuning_store.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/input_file.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

constexpr int kFormatVersion = 1;

// log2 of the class's bound ("n<=1024": 10). Throws UserError unless the
// class is "n<=" and a power of two in decimal digits.
int class_exponent(const std::string& size_class) {
  const std::string prefix = "n<=";
  std::uint64_t bound = 0;
  const char* end = size_class.data() + size_class.size();
  const bool has_prefix = size_class.rfind(prefix, 0) == 0;
  const auto [stop, error] =
      has_prefix ? std::from_chars(size_class.data() + prefix.size(), end, bound) : std::from_chars_result{};
  if (!has_prefix || error != std::errc{} || stop != end || !std::has_single_bit(bound)) {
    throw UserError("size class \"" + size_class + "\" is not n<=N with N a power of two");
  }
  return std::bit_width(bound) - 1;
}

// A whole number above 0 (JSON 32.7 or -3 is refused, not truncated).
std::size_t positive_whole_number(const nlohmann::json& entry, const char* key) {
  const nlohmann::json& value = entry.at(key);
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() == 0) {
    throw UserError(std::string(key) + " " + value.dump() + " is not a whole number above 0");
  }
  return value.get<std::size_t>();
}

nlohmann::json to_json(const TunedSizes& sizes) {
  nlohmann::json entry = {{"device", sizes.device},
                          {"kernel", sizes.kernel},
                          {"size_class", sizes.size_class},
                          {"wg", sizes.work_group_size},
                          {"median_ms", sizes.median_ms},
                          {"measured_on", sizes.measured_on}};
  if (sizes.tile_size > 0) entry["tile"] = sizes.tile_size;
  return entry;
}

TunedSizes from_json(const nlohmann::json& entry) {
  TunedSizes sizes;
  sizes.device = entry.at("device").get<std::string>();
  sizes.kernel = entry.at("kernel").get<std::string>();
  sizes.size_class = entry.at("size_class").get<std::string>();
  class_exponent(sizes.size_class);  // throws when malformed
  sizes.work_group_size = positive_whole_number(entry, "wg");
  if (entry.contains("tile")) sizes.tile_size = positive_whole_number(entry, "tile");
  sizes.median_ms = entry.value("median_ms", 0.0);
  sizes.measured_on = entry.value("measured_on", "");
  return sizes;
}

}  // namespace

std::optional<std::filesystem::path> default_tuning_file() {
  // No fallback to the temporary directory: a tuning file there would be
  // lost at the next reboot, and anyone could put one there for us.
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    return std::filesystem::path(xdg) / "meshparticles" / "tuning.json";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "meshparticles" / "tuning.json";
  }
  return std::nullopt;
}

std::optional<std::filesystem::path> tuning_file_or_default(const std::string& option) {
  if (option.empty()) return default_tuning_file();
  return std::filesystem::path(option);
}

std::string size_class(std::size_t particles) { return "n<=" + std::to_string(std::bit_ceil(particles)); }

TuningStore TuningStore::load(const std::filesystem::path& file, const std::vector<std::string>& kernels) {
  TuningStore store;
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return store;
  store.file_found_ = true;
  const std::string text = read_input_text(file, "tuning file " + file.string());
  try {
    const nlohmann::json document = nlohmann::json::parse(text);
    if (document.at("version").get<int>() != kFormatVersion) throw UserError("unknown version");
    for (const auto& entry : document.at("entries")) {
      TunedSizes sizes = from_json(entry);
      if (std::find(kernels.begin(), kernels.end(), sizes.kernel) == kernels.end()) {
        throw UserError("unknown kernel '" + sizes.kernel + "'");
      }
      store.put(sizes);
    }
  } catch (const std::exception& problem) {
    throw UserError("tuning file " + file.string() + " is not readable (" + problem.what() +
                    "); move it away or fix it");
  }
  return store;
}

std::optional<TunedSizes> TuningStore::find(const std::string& device, const std::string& kernel,
                                            std::size_t particles) const {
  const int wanted = class_exponent(size_class(particles));
  std::optional<TunedSizes> nearest;
  for (const TunedSizes& entry : entries_) {
    if (entry.device != device || entry.kernel != kernel) continue;
    const int distance = std::abs(class_exponent(entry.size_class) - wanted);
    if (!nearest || distance < std::abs(class_exponent(nearest->size_class) - wanted)) nearest = entry;
  }
  return nearest;
}

void TuningStore::put(const TunedSizes& sizes) {
  // An index keeps loading a file of many entries linear, not quadratic.
  const auto [place, added] = index_.try_emplace({sizes.device, sizes.kernel, sizes.size_class}, entries_.size());
  if (added) {
    entries_.push_back(sizes);
  } else {
    entries_[place->second] = sizes;
  }
}

void TuningStore::save(const std::filesystem::path& file) const {
  nlohmann::json entries = nlohmann::json::array();
  for (const TunedSizes& entry : entries_) entries.push_back(to_json(entry));
  const nlohmann::json document = {{"version", kFormatVersion}, {"entries", entries}};
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  if (error) throw UserError("cannot create " + file.parent_path().string() + ": " + error.message());
  write_file_atomically(file, [&](std::ostream& out) { out << json_text(document, 2) << "\n"; });
}

}  // namespace meshparticles
