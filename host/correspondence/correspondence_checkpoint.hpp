#pragma once
// What a `correspond` that was killed had finished, kept in DIR/checkpoint/
// so that the same command run again goes on from there (as `batch` reuses
// the meshes it finished): the template's particles, each shape's transfer,
// every shape's particles after the iterations and after the packing (each
// stage with its record), and each shape's measured result. A run of other
// inputs (their paths, sizes and times) or other parameters starts anew.
// Each file is written whole (atomically); a stage counts only once its
// record is written, after every shape's file of it. The folder is removed
// once the outputs are in place.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace meshparticles {

class CorrespondCheckpoint {
 public:
  // The checkpoint folder of output directory `directory`, for a run that
  // `fingerprint` describes. The leader (the one process, or rank 0) clears
  // one that another run left, before any other process reads it.
  CorrespondCheckpoint(const std::filesystem::path& directory, nlohmann::json fingerprint, bool leader, bool quiet);

  // `name` as "template", "transfer/007"; absent when not written yet.
  std::optional<nlohmann::json> read(const std::string& name) const;
  void write(const std::string& name, const nlohmann::json& value) const;
  // Once the outputs are written: the folder goes.
  void remove() const;

  static constexpr const char* kFolder = "checkpoint";

 private:
  std::filesystem::path folder_;
};

// "transfer/007": a stage's file for shape k.
std::string shape_entry(const std::string& stage, std::size_t shape);

}  // namespace meshparticles
