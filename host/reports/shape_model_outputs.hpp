#pragma once
// The files of a statistical shape model, written as one set
// (common/atomic_directory): the aligned shapes, the mean, the modes and
// their variances (CSV and JSON), the alignment transforms and the model
// measures. docs/CORRESPONDENCE.md lists each file.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shape_model/model_quality.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles {

struct ShapeModelOutputs {
  std::vector<std::string> shapes;  // the input files, as given
  const ProcrustesAlignment* alignment = nullptr;
  const ShapeModes* model = nullptr;
  const ModelQuality* quality = nullptr;
  nlohmann::json params;  // what was asked, for model.json
};

// "000_NAME.aligned.particles" for each input, in order (unique whatever
// the names).
std::vector<std::string> aligned_file_names(const std::vector<std::string>& shapes);

// Throws UserError before any work when `directory` cannot take the set.
void prepare_shape_model_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes);

// model.json's content: the inputs, the alignment, the variances and the
// measures (everything but the point coordinates).
nlohmann::json shape_model_summary(const ShapeModelOutputs& outputs);

void write_shape_model(const std::filesystem::path& directory, const ShapeModelOutputs& outputs);

}  // namespace meshparticles
