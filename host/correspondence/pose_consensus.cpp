#include "correspondence/pose_consensus.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace meshparticles {

namespace {

// A candidate replaces the held pose only where its summed distance is this
// much less: where the population barely tells them apart, the shape's own
// fit onto the template stands.
constexpr double kClearlyNearer = 1.01;
constexpr std::size_t kRounds = 10;

}  // namespace

PoseCandidates::PoseCandidates(std::vector<std::vector<PointSet>> placed) : placed_(std::move(placed)) {
  trees_.resize(placed_.size());
  for (std::size_t j = 0; j < std::min(kReferences, placed_.size()); ++j) {
    for (const PointSet& points : placed_[j]) trees_[j].push_back(std::make_unique<PointsTree>(points));
  }
}

std::vector<std::size_t> PoseCandidates::references(std::size_t shape) const {
  std::vector<std::size_t> found;
  for (std::size_t j = 0; j < std::min(kReferences, placed_.size()); ++j) {
    if (j != shape) found.push_back(j);
  }
  return found;
}

std::vector<double> PoseCandidates::distances(std::size_t shape) const {
  std::vector<double> row;
  if (candidates(shape) < 2) return row;
  for (const PointSet& own : placed_[shape]) {
    for (const std::size_t j : references(shape)) {
      for (std::size_t b = 0; b < candidates(j); ++b) row.push_back(fitted_shape_distance(own, placed_[j][b], *trees_[j][b]));
    }
  }
  return row;
}

std::vector<PoseChoice> PoseCandidates::choose(const std::vector<std::vector<double>>& distances) const {
  const std::size_t count = shapes();
  std::vector<PoseChoice> choices(count);
  std::vector<std::size_t> open;  // the shapes with more than one candidate
  for (std::size_t k = 0; k < count; ++k) {
    if (candidates(k) > 1) open.push_back(k);
  }
  if (count < 3) return choices;  // two shapes: the population is the template

  // Shape k's candidate a's summed distance to the references as chosen.
  const auto summed = [&](std::size_t k, std::size_t a) {
    const std::vector<std::size_t> others = references(k);
    std::size_t per_candidate = 0;
    for (const std::size_t j : others) per_candidate += candidates(j);
    std::size_t at = a * per_candidate;
    double sum = 0;
    for (const std::size_t j : others) {
      sum += distances[k][at + choices[j].chosen];
      at += candidates(j);
    }
    return sum;
  };
  for (std::size_t round = 0; round < kRounds; ++round) {
    bool changed = false;
    for (const std::size_t k : open) {
      std::size_t nearest = choices[k].chosen;
      for (std::size_t a = 0; a < candidates(k); ++a) {
        if (summed(k, a) < summed(k, nearest)) nearest = a;
      }
      if (summed(k, nearest) * kClearlyNearer >= summed(k, choices[k].chosen)) continue;
      choices[k].chosen = nearest;
      changed = true;
    }
    if (!changed) break;
  }
  for (const std::size_t k : open) {
    double other = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < candidates(k); ++a) {
      if (a != choices[k].chosen) other = std::min(other, summed(k, a));
    }
    choices[k].ratio = other > 0 ? summed(k, choices[k].chosen) / other : 1;
  }
  return choices;
}

}  // namespace meshparticles
