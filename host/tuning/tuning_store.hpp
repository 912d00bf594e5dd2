#pragma once
// The best sizes `sweep --save` found, per device, kernel (a device
// backend's name) and problem size
// class, in $XDG_CONFIG_HOME/meshparticles/tuning.json (else
// ~/.config/meshparticles/tuning.json). `run` and `bench` take their sizes
// from it when --wg and --tile are absent.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>


namespace meshparticles {

// $XDG_CONFIG_HOME/meshparticles/tuning.json, else
// $HOME/.config/meshparticles/tuning.json; nothing when neither is set.
std::optional<std::filesystem::path> default_tuning_file();
// --tuning-file as given, or default_tuning_file() when it is empty.
std::optional<std::filesystem::path> tuning_file_or_default(const std::string& option);

// Problems are grouped by particle count, rounded up to a power of two:
// "n<=1024" holds 513..1024 particles.
std::string size_class(std::size_t particles);

struct TunedSizes {
  std::string device;
  std::string kernel;          // a device backend's name: "tiled"
  std::string size_class;
  std::size_t work_group_size = 0;
  std::size_t tile_size = 0;  // 0: the kernel takes no tile
  double median_ms = 0;       // what the sweep measured
  std::string measured_on;    // mesh and n of that sweep
};

class TuningStore {
 public:
  // An empty store when the file does not exist; UserError naming the file
  // when it exists but cannot be read as a tuning file, or names a kernel
  // not among `kernels` (the device backends' names).
  static TuningStore load(const std::filesystem::path& file, const std::vector<std::string>& kernels);

  // The entry of this device and kernel for this size class, else the one of
  // the nearest size class measured for them; nothing when there is none.
  std::optional<TunedSizes> find(const std::string& device, const std::string& kernel, std::size_t particles) const;
  // Adds `sizes`, replacing any entry with the same device, kernel and class.
  void put(const TunedSizes& sizes);
  // Atomically; entries of other devices and classes are kept.
  void save(const std::filesystem::path& file) const;

  const std::vector<TunedSizes>& entries() const { return entries_; }
  // Whether load() found a file (an empty store may come from none).
  bool file_found() const { return file_found_; }

 private:
  std::vector<TunedSizes> entries_;
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> index_;  // device, kernel, class
  bool file_found_ = false;
};

}  // namespace meshparticles
