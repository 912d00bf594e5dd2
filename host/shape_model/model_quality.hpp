#pragma once
// What shape-model papers report of a model, for each number of modes M
// (Davies, Twining and Taylor; Styner et al. 2003):
// - compactness: the share of the total variance the first M modes hold;
// - generalization: how well a model built without a shape rebuilds it
//   from M modes (leave one out): the mean distance between its points and
//   the rebuilt ones, averaged over the shapes;
// - specificity: how close shapes drawn from the model (M modes, normal
//   weights of the modes' variances) come to the nearest training shape.
// Lower generalization and specificity are better; both are in the units
// of the aligned points (the inputs' units, see ProcrustesAlignment).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shape_model/shape_modes.hpp"

namespace meshparticles {

struct ModelMeasure {
  double mean = 0, sd = 0;
};

struct ModelQuality {
  // Index M - 1 for M modes.
  std::vector<double> compactness;             // M = 1 .. all modes
  std::vector<ModelMeasure> generalization;    // M = 1 .. S - 2 (a model of S - 1 shapes)
  std::vector<ModelMeasure> specificity;       // M = 1 .. all modes
  std::size_t samples = 0;                     // drawn per M for specificity
};

// The leave-one-out models reuse the whole population's alignment (the
// usual shortcut: one alignment, S small models). Deterministic for a seed.
// Unless `quiet`, a progress line on stderr (specificity is most of the work).
ModelQuality measure_model(const std::vector<PointSet>& aligned, const ShapeModes& model, std::size_t samples,
                           std::uint64_t seed, bool quiet = true);

}  // namespace meshparticles
