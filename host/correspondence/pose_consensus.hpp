#pragma once
// Which of its possible poses each shape of a population takes, chosen by
// the population rather than by its fit onto the template alone. A shape
// that is almost its own half turn (a bent body whose few small bumps alone
// say which end is which) fits the template nearly as well either way
// round, and one pairwise fit picks the wrong pose about as often as the
// features are faint. Placed each way round, it lies nearer the other
// shapes in one of them: many shapes, each placed by its own fit, outvote
// one fit's noise.
#include <cstddef>
#include <memory>
#include <vector>

#include "correspondence/mesh_alignment.hpp"

namespace meshparticles {

struct PoseChoice {
  std::size_t chosen = 0;  // the candidate taken
  // Its summed distance to the references over the nearest other
  // candidate's (under 1: the population prefers it); 0 where the shape
  // had one candidate.
  double ratio = 0;
};

class PoseCandidates {
 public:
  // The shapes every shape is compared with: the first this many.
  static constexpr std::size_t kReferences = 16;

  // `placed[k]`: shape k's points in the common frame in each of its
  // candidate poses (stretched_pose), its own fit's choice first. One
  // candidate: the shape's pose is settled (the template's, a body's), and
  // it only serves the others; none: a settled shape past the references.
  explicit PoseCandidates(std::vector<std::vector<PointSet>> placed);
  PoseCandidates(const PoseCandidates&) = delete;  // the trees read the points where they are
  PoseCandidates& operator=(const PoseCandidates&) = delete;

  std::size_t shapes() const { return placed_.size(); }
  std::size_t candidates(std::size_t shape) const { return placed_[shape].size(); }

  // Shape k's candidates' distances to the references' candidates (for
  // each of k's candidates, each reference but k, each of its candidates:
  // fitted_shape_distance), the work of k's owner; empty for a shape with
  // one candidate. The references are the first 16 shapes (the template
  // among them), so that the work grows with the shapes, not their square.
  std::vector<double> distances(std::size_t shape) const;

  // Every shape's choice from every shape's distances: each shape with
  // several candidates takes the one whose summed distance to the
  // references, as they are chosen so far, is least, in rounds over the
  // shapes in order until none changes (each shape's own fit's choice to
  // start; a candidate replaces the held one only where it is clearly
  // nearer). Every process makes the same choices from the same distances.
  std::vector<PoseChoice> choose(const std::vector<std::vector<double>>& distances) const;

 private:
  std::vector<std::size_t> references(std::size_t shape) const;

  std::vector<std::vector<PointSet>> placed_;
  std::vector<std::vector<std::unique_ptr<PointsTree>>> trees_;  // the references' candidates'
};

}  // namespace meshparticles
