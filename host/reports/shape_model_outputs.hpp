#pragma once
// The files of a statistical shape model, written as one set
// (common/atomic_directory): the aligned shapes, the mean, the modes and
// their variances (CSV and JSON), the alignment transforms and the model
// measures (ours, and ShapeWorks' beside them). docs/CORRESPONDENCE.md lists each file.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shape_model/shape_model.hpp"

namespace meshparticles {

struct ShapeModelOutputs {
  std::vector<std::string> shapes;  // the input files, as given
  const ShapeModel* model = nullptr;
  nlohmann::json params;  // what was asked, for model.json
};

// "000_NAME" for each input file, in order: unique whatever the names, the
// stem of every per-shape file (here and in correspond's shapes/).
std::vector<std::string> indexed_stems(const std::vector<std::string>& shapes);

// Throws UserError before any work when `directory` cannot take the set.
void prepare_shape_model_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes);

// model.json's content: the inputs, the alignment, the variances and the
// measures (everything but the point coordinates).
nlohmann::json shape_model_summary(const ShapeModelOutputs& outputs);

void write_shape_model(const std::filesystem::path& directory, const ShapeModelOutputs& outputs);

}  // namespace meshparticles
