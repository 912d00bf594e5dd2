#pragma once
// What a `correspond` that was killed had finished, kept in DIR/checkpoint/
// so that the same command run again goes on from there (as `batch` reuses
// the meshes it finished): the template's particles, each shape's transfer,
// every shape's particles after the iterations and after the packing (each
// stage with its record), and each shape's measured result. A run of other
// inputs (their paths, sizes and times) or other parameters starts anew.
// Each file is written whole (atomically); a stage counts only once its
// record is written, after every shape's file of it. The folder goes once
// the outputs are in place: it stays in the --out that the new set replaces
// whole (correspondence_outputs.hpp).
//
// A checkpoint is not trusted blindly. Each entry is two lines: a header
// naming the entry, the request it belongs to and the size and SHA-256 of
// the second line, the values. The leader checks every entry before the
// run takes any: one that was edited, cut short or moved makes the whole
// checkpoint damaged, and the run removes it and starts anew; so does an
// entry that is not a file (a folder named like one). A decode that finds
// values no run of this request could have written refuses in one line,
// after removing the checkpoint: checked against what the request fixes,
// so an entry re-signed after an edit is not taken either - an id past the
// mesh, a row short, a particle count other than -n, barycentric weights
// outside [0, 1] or not summing to 1, an entry of another shape's mesh.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace meshparticles {

class CorrespondCheckpoint {
 public:
  // The checkpoint folder of output directory `directory`, for a run that
  // `fingerprint` describes. The leader (the one process, or rank 0) clears
  // one that another run left, or that is damaged, before any other process
  // reads it.
  CorrespondCheckpoint(const std::filesystem::path& directory, const nlohmann::json& fingerprint, bool leader,
                       bool quiet);

  // `name` as "template", "transfer/007": its values, decoded by `decode`;
  // absent when not written yet. `decode` throws nlohmann::json's exceptions
  // or std::invalid_argument on values it cannot take; those refuse the run
  // (UserError) after the folder is removed.
  template <typename Decode>
  auto read(const std::string& name, Decode&& decode) const -> std::optional<decltype(decode(nlohmann::json()))> {
    const std::optional<nlohmann::json> values = read_values(name);
    if (!values) return std::nullopt;
    try {
      return decode(*values);
    } catch (const nlohmann::json::exception& error) {
      refuse(name, error.what());
    } catch (const std::invalid_argument& error) {
      refuse(name, error.what());
    }
  }
  void write(const std::string& name, const nlohmann::json& values) const;

  static constexpr const char* kFolder = "checkpoint";

 private:
  std::optional<nlohmann::json> read_values(const std::string& name) const;
  [[noreturn]] void refuse(const std::string& name, const std::string& why) const;

  std::filesystem::path folder_;
  std::string request_digest_;
  // Set once a damaged entry refused the run: the other threads of a stage
  // neither read nor write the folder after it is removed (a write would
  // make it again). Writes and the removal hold the mutex.
  mutable std::atomic<bool> removed_{false};
  mutable std::mutex writing_;
};

// "transfer/007": a stage's file for shape k.
std::string shape_entry(const std::string& stage, std::size_t shape);

}  // namespace meshparticles
