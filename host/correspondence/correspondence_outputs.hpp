#pragma once
// What `meshparticles correspond` writes in its --out folder:
//   shapes/NNN_NAME.particles  particle i of every shape on row i (world)
//   shapes/NNN_NAME.csv        particle, vertex (the nearest corner's id in the
//                              file), x, y, z, and the triangle and weights, as
//                              run's particles.csv
//   model/                     the shape model of those particles
//                              (reports/shape_model_outputs: aligned shapes,
//                              mean, modes, transforms, measures)
//   summary.json               the template's run, each shape's fit and the
//                              model's measures
//   checkpoint/                while the run goes (correspondence_checkpoint)
// The set is replaced as a whole: built beside the folder and swapped in
// for it at once (common/atomic_directory), the old set and the checkpoint
// going with the folder it replaces; a reader or a kill finds the old set
// or the new one, whole. So the folder's parent must take new entries, and
// the folder cannot be a mount point (both refused before the work).
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "correspondence/population_correspondence.hpp"
#include "reports/shape_model_outputs.hpp"

namespace meshparticles {

// Throws UserError before any work when the folder cannot take the outputs.
// Called holding the folder's lock: first removes what a killed run left
// in it and beside it, whatever host or process that run had.
void prepare_correspondence_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes);

void write_correspondence(const std::filesystem::path& directory, const PopulationCorrespondence& population,
                          const ShapeModelOutputs& model, nlohmann::json summary);

}  // namespace meshparticles
