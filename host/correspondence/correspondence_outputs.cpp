#include "correspondence/correspondence_outputs.hpp"

#include <cstdio>
#include <set>

#include "common/atomic_directory.hpp"
#include "common/atomic_file.hpp"
#include "common/exact_number.hpp"
#include "common/json_text.hpp"
#include "common/temporary_names.hpp"
#include "common/user_error.hpp"
#include "correspondence/correspondence_checkpoint.hpp"

namespace meshparticles {

namespace {

std::set<std::string> shape_files(const std::vector<std::string>& shapes) {
  std::set<std::string> names;
  for (const std::string& stem : indexed_stems(shapes)) {
    names.insert(stem + ".particles");
    names.insert(stem + ".csv");
  }
  return names;
}

}  // namespace

void prepare_correspondence_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes) {
  std::error_code error;
  // What a killed run left while writing its outputs (.shapes.tmp-…,
  // .summary.tmp-….json) goes first: the checkpoint beside it lets the
  // same command go on, as the README promises.
  remove_stale_temporaries(directory);
  if (std::filesystem::exists(directory, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
      const std::string name = entry.path().filename().string();
      if (name != "shapes" && name != "model" && name != "summary.json" && name != CorrespondCheckpoint::kFolder) {
        throw UserError("output directory " + directory.string() + " holds " + name +
                        ", which is not an output of correspond: give a directory of its own");
      }
    }
  }
  check_replaceable_directory(directory / "shapes", shape_files(shapes));
  prepare_shape_model_directory(directory / "model", shapes);
}

void write_correspondence(const std::filesystem::path& directory, const PopulationCorrespondence& population,
                          const ShapeModelOutputs& model, nlohmann::json summary) {
  const std::vector<std::string> stems = indexed_stems(model.shapes);
  write_directory_atomically(directory / "shapes", shape_files(model.shapes), [&](const std::filesystem::path& staging) {
    for (std::size_t s = 0; s < population.shapes.size(); ++s) {
      const ShapeCorrespondence& shape = population.shapes[s];
      char line[320];
      write_new_file(staging / (stems[s] + ".particles"), [&](std::ostream& out) {
        for (Eigen::Index i = 0; i < shape.particles.rows(); ++i) {
          out << exact_triple(shape.particles(i, 0), shape.particles(i, 1), shape.particles(i, 2)) << "\n";
        }
      });
      write_new_file(staging / (stems[s] + ".csv"), [&](std::ostream& out) {
        out << "particle,vertex,x,y,z,corner_a,corner_b,corner_c,weight_a,weight_b,weight_c\n";
        for (Eigen::Index i = 0; i < shape.particles.rows(); ++i) {
          const InputLocation& at = shape.locations[std::size_t(i)];
          std::snprintf(line, sizeof line, ",%u,%u,%u,%.17g,%.17g,%.17g\n", unsigned(at.corners[0]),
                        unsigned(at.corners[1]), unsigned(at.corners[2]), at.weights[0], at.weights[1], at.weights[2]);
          out << i << "," << at.heaviest_corner() << ","
              << exact_triple(shape.particles(i, 0), shape.particles(i, 1), shape.particles(i, 2), ',') << line;
        }
      });
    }
  });
  write_shape_model(directory / "model", model);
  write_file_atomically(directory / "summary.json", [&](std::ostream& out) { out << json_text(summary, 2) << "\n"; });
}

}  // namespace meshparticles
