#pragma once
// Holds a kernel's choices to the serial reference's rule on one
// configuration: what the sweep verifies before it times a configuration, and
// what the agreement tests assert at every kernel size.
#include <span>
#include <string>
#include <vector>

#include "backends/serial_backend.hpp"

namespace meshparticles {

struct ChoiceVerdict {
  std::size_t wrong = 0;           // choices outside the tolerance
  std::size_t ranked_choices = 0;  // particles with a candidate of their stack rank
  std::size_t exact_checks = 0;    // of those, the ones whose choice is unique by more than the tolerance
  std::string first_wrong;         // a sentence about the first wrong choice, if any
};

// The reference's candidate energies (double) for every particle of one
// configuration, computed once and checked against any number of kernels.
// The tolerance a kernel's choices are held to: 1e-5 relative for float32
// weights; 1e-3 for the half-precision table of the field backends, whose
// weights are each rounded to 11 significant bits (2^-11 = 4.9e-4).
double choice_tolerance(WeightFormat weights);

class ReferenceChoices {
 public:
  // A choice is right when its energy is within `tolerance` (relative) of the
  // energy of the candidate the rule picks, and exactly that candidate when
  // no other is that close.
  ReferenceChoices(const SurfaceMesh& mesh, const SerialBackend& reference, std::vector<VertexId> positions,
                   double tolerance = 1e-5);

  // `chosen`: the vertex of every particle after one synchronous step.
  ChoiceVerdict check(std::span<const VertexId> chosen) const { return check(chosen, tolerance_); }
  ChoiceVerdict check(std::span<const VertexId> chosen, double tolerance) const;

 private:
  const SurfaceMesh& mesh_;
  std::vector<VertexId> positions_;
  double tolerance_;
  std::vector<std::vector<double>> energies_;  // per particle, per candidate
  std::vector<std::size_t> stack_ranks_;
};

}  // namespace meshparticles
