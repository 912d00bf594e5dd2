#include "tuning/tuning_store.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

constexpr int kFormatVersion = 1;

// log2 of the class's bound, for "nearest class".
int class_exponent(const std::string& size_class) {
  const std::size_t bound = std::stoull(size_class.substr(size_class.find("<=") + 2));
  return std::bit_width(bound) - 1;
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
  sizes.work_group_size = entry.at("wg").get<std::size_t>();
  if (entry.contains("tile")) {
    sizes.tile_size = entry.at("tile").get<std::size_t>();
    if (sizes.tile_size == 0) throw UserError("a tile of 0");
  }
  if (sizes.work_group_size == 0) throw UserError("a work-group size of 0");
  sizes.median_ms = entry.value("median_ms", 0.0);
  sizes.measured_on = entry.value("measured_on", "");
  return sizes;
}

}  // namespace

std::filesystem::path default_tuning_file() {
  std::filesystem::path directory;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    directory = xdg;
  } else if (const char* home = std::getenv("HOME"); home && *home) {
    directory = std::filesystem::path(home) / ".config";
  } else {
    directory = std::filesystem::temp_directory_path();
  }
  return directory / "meshparticles" / "tuning.json";
}

std::filesystem::path tuning_file_or_default(const std::string& option) {
  return option.empty() ? default_tuning_file() : std::filesystem::path(option);
}

std::string size_class(std::size_t particles) { return "n<=" + std::to_string(std::bit_ceil(particles)); }

TuningStore TuningStore::load(const std::filesystem::path& file, const std::vector<std::string>& kernels) {
  TuningStore store;
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return store;
  std::ifstream in(file);
  try {
    const nlohmann::json document = nlohmann::json::parse(in);
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
  for (TunedSizes& entry : entries_) {
    if (entry.device == sizes.device && entry.kernel == sizes.kernel && entry.size_class == sizes.size_class) {
      entry = sizes;
      return;
    }
  }
  entries_.push_back(sizes);
}

void TuningStore::save(const std::filesystem::path& file) const {
  nlohmann::json entries = nlohmann::json::array();
  for (const TunedSizes& entry : entries_) entries.push_back(to_json(entry));
  const nlohmann::json document = {{"version", kFormatVersion}, {"entries", entries}};
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  if (error) throw UserError("cannot create " + file.parent_path().string() + ": " + error.message());
  write_file_atomically(file, [&](std::ostream& out) { out << document.dump(2) << "\n"; });
}

}  // namespace meshparticles
