#pragma once
// A statistical shape model of corresponding point sets, whole: the
// Procrustes alignment, the modes of the aligned shapes and the measures of
// the model, in the one order every caller (`model`, `correspond`) needs.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shape_model/model_quality.hpp"
#include "shape_model/procrustes.hpp"
#include "shape_model/shape_modes.hpp"

namespace meshparticles {

struct ShapeModel {
  ProcrustesAlignment alignment;
  ShapeModes modes;
  ModelQuality quality;
};

// `samples` and `seed`: specificity's draws; `quiet`: no progress line.
inline ShapeModel build_shape_model(const std::vector<PointSet>& shapes, bool with_scale, std::size_t samples,
                                    std::uint64_t seed, bool quiet) {
  ShapeModel model;
  model.alignment = align_procrustes(shapes, with_scale);
  model.modes = principal_modes(model.alignment.aligned);
  model.quality = measure_model(model.alignment.aligned, model.modes, samples, seed, quiet);
  return model;
}

}  // namespace meshparticles
