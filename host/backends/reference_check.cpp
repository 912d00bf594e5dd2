#include "backends/reference_check.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "particles/energy.hpp"

namespace meshparticles {

namespace {

// The candidate indices of one particle, best first.
std::vector<std::size_t> ranked(const std::vector<double>& energies) {
  std::vector<std::size_t> order(energies.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return ranks_before(energies[a], a, energies[b], b); });
  return order;
}

}  // namespace

ReferenceChoices::ReferenceChoices(const SurfaceMesh& mesh, const SerialBackend& reference,
                                   std::vector<VertexId> positions, double tolerance)
    : mesh_(mesh), positions_(std::move(positions)), tolerance_(tolerance) {
  std::unordered_map<VertexId, std::size_t> seen;  // particles met so far on each vertex
  for (std::size_t c = 0; c < positions_.size(); ++c) {
    energies_.push_back(reference.candidate_energies(c, positions_));
    stack_ranks_.push_back(seen[positions_[c]]++);
  }
}

double choice_tolerance(WeightFormat weights) { return weights == WeightFormat::half ? 1e-3 : 1e-5; }

ChoiceVerdict ReferenceChoices::check(std::span<const VertexId> chosen, double tolerance) const {
  ChoiceVerdict verdict;
  auto wrong = [&](std::size_t c, const std::string& what) {
    if (verdict.wrong++ == 0) verdict.first_wrong = "particle " + std::to_string(c) + " " + what;
  };
  for (std::size_t c = 0; c < positions_.size(); ++c) {
    const VertexId here = positions_[c];
    const std::vector<double>& energies = energies_[c];
    const std::vector<std::size_t> order = ranked(energies);
    const std::size_t rank = stack_ranks_[c];
    if (rank >= energies.size() || std::isinf(energies[order[rank]])) {
      if (chosen[c] != here) wrong(c, "moved although it has no free candidate of its stack rank");
      continue;
    }
    const auto ring = mesh_.one_ring(here);
    std::size_t got = energies.size();
    if (chosen[c] == here) {
      got = 0;
    } else if (const auto it = std::find(ring.begin(), ring.end(), chosen[c]); it != ring.end()) {
      got = std::size_t(it - ring.begin()) + 1;
    }
    if (got == energies.size()) {
      wrong(c, "jumped to vertex " + std::to_string(chosen[c]) + ", not one of its candidates");
      continue;
    }
    const std::size_t want = order[rank];
    const double scale = std::max(std::abs(energies[want]), 1e-30);
    const auto close = [&](std::size_t j) { return std::abs(energies[j] - energies[want]) <= tolerance * scale; };
    ++verdict.ranked_choices;
    bool unique = true;
    for (std::size_t j = 0; j < energies.size(); ++j) unique = unique && (j == want || !close(j));
    if (unique) ++verdict.exact_checks;
    if (!close(got) || (unique && got != want)) {
      wrong(c, "chose candidate " + std::to_string(got) + " (energy " + std::to_string(energies[got]) +
                   "), the reference candidate " + std::to_string(want) + " (energy " +
                   std::to_string(energies[want]) + ")");
    }
  }
  return verdict;
}

}  // namespace meshparticles
