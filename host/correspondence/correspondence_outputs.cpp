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

// What --out holds: the outputs, and the checkpoint until they are written.
const std::set<std::string> kOutputNames = {"shapes", "model", "summary.json", CorrespondCheckpoint::kFolder};

std::set<std::string> shape_files(const std::vector<std::string>& shapes) {
  std::set<std::string> names;
  for (const std::string& stem : indexed_stems(shapes)) {
    names.insert(stem + ".particles");
    names.insert(stem + ".csv");
  }
  return names;
}

// shapes/ of the set being built in `set`.
void write_shape_files(const std::filesystem::path& set, const PopulationCorrespondence& population,
                       const std::vector<std::string>& shapes) {
  const std::vector<std::string> stems = indexed_stems(shapes);
  write_directory_atomically(set / "shapes", shape_files(shapes), [&](const std::filesystem::path& staging) {
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
}

}  // namespace

void prepare_correspondence_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes) {
  std::error_code error;
  // What a killed run left while writing its outputs goes first, whatever
  // host, container or process it ran in (the caller holds --out's lock, so
  // no writer of it is alive): beside --out the new set it was writing or
  // the old set it was removing, and inside it the temporaries of earlier
  // versions (.shapes.tmp-…). The checkpoint lets the same command go on.
  remove_leftovers_beside(directory);
  remove_stale_temporaries(directory, Writers::none);
  if (std::filesystem::exists(directory, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
      const std::string name = entry.path().filename().string();
      if (!kOutputNames.count(name)) {
        throw UserError("output directory " + directory.string() + " holds " + name +
                        ", which is not an output of correspond: give a directory of its own");
      }
    }
  }
  check_replaceable_directory(directory / "shapes", shape_files(shapes));
  prepare_shape_model_directory(directory / "model", shapes);
  check_replaceable_directory(directory, kOutputNames);  // its parent takes the new set; no mount point
}

void write_correspondence(const std::filesystem::path& directory, const PopulationCorrespondence& population,
                          const ShapeModelOutputs& model, nlohmann::json summary) {
  // The whole set is built beside --out, then swapped in for it at once: a
  // reader, or a run killed at any moment, finds the old set or the new one,
  // whole. The old set and the checkpoint go with the directory it replaces.
  write_directory_atomically(directory, kOutputNames, [&](const std::filesystem::path& set) {
    write_shape_files(set, population, model.shapes);
    write_shape_model(set / "model", model);
    write_file_atomically(set / "summary.json", [&](std::ostream& out) { out << json_text(summary, 2) << "\n"; });
  });
}

}  // namespace meshparticles
