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
//
// Beside ours, the same three as ShapeWorks computes them
// (Libs/Particles/ShapeEvaluation.cpp, its "full" curves), so figures can be
// set beside ShapeWorks Studio's: M = 1 .. S - 1 always; generalization and
// specificity as means only; specificity from 1,000 drawn shapes whose mode
// weights have as their variance the mode's singular value of the centred
// S-shape data matrix, sqrt((S - 1) variance), not the mode's variance (so
// ShapeWorks' specificity depends on the points' unit). docs/CORRESPONDENCE.md
// says where each convention differs.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shape_model/shape_modes.hpp"

namespace meshparticles {

struct ModelMeasure {
  double mean = 0, sd = 0;
};

// Index M - 1 for M modes, M = 1 .. S - 1; empty when the shapes are one
// shape (no mode: ShapeWorks would divide by a total variance of 0).
struct ShapeWorksMeasures {
  std::vector<double> compactness;
  // For M = S - 1 ShapeWorks' left-out model of S - 1 shapes adds a
  // direction of zero variance that its SVD picks by rounding; here the
  // rebuild keeps the S - 2 modes the shapes hold (the last figure repeats).
  std::vector<double> generalization;
  std::vector<double> specificity;
  static constexpr std::size_t kSamples = 1000;  // ShapeWorks' fixed count
};

struct ModelQuality {
  // Index M - 1 for M modes.
  std::vector<double> compactness;             // M = 1 .. all modes
  std::vector<ModelMeasure> generalization;    // M = 1 .. S - 2 (a model of S - 1 shapes)
  std::vector<ModelMeasure> specificity;       // M = 1 .. all modes
  std::size_t samples = 0;                     // drawn per M for specificity
  ShapeWorksMeasures shapeworks;
};

// The leave-one-out models reuse the whole population's alignment (the
// usual shortcut: one alignment, S small models). Deterministic for a seed.
// ShapeWorks' specificity draws from its own stream of `seed`, so ours
// do not depend on it nor it on `samples`.
// Unless `quiet`, a progress line on stderr (specificity is most of the work).
ModelQuality measure_model(const std::vector<PointSet>& aligned, const ShapeModes& model, std::size_t samples,
                           std::uint64_t seed, bool quiet = true);

}  // namespace meshparticles
