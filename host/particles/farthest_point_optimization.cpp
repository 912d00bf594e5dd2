#include "particles/farthest_point_optimization.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <unordered_set>
#include <vector>

#include "common/progress.hpp"
#include "common/random.hpp"
#include "particles/particle_voronoi.hpp"

namespace meshparticles {

namespace {

// A set of positions in 64 bits: SplitMix64 over each in turn.
std::uint64_t positions_hash(const std::vector<VertexId>& positions) {
  std::uint64_t hash = positions.size();
  for (const VertexId v : positions) hash = SplitMix64(hash ^ v).next();
  return hash;
}

}  // namespace

SpreadOutcome optimize_farthest_points(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                       const std::vector<VertexId>& start, std::size_t max_sweeps, double min_gain,
                                       double stall_gain, bool quiet, std::unique_ptr<ParticleVoronoi> diagram) {
  SpreadOutcome outcome;
  outcome.positions = start;
  const auto count = std::uint32_t(start.size());
  if (max_sweeps == 0 || count < 2) {
    outcome.converged = count < 2;
    return outcome;
  }
  if (!diagram) {
    diagram = std::make_unique<ParticleVoronoi>(mesh, solver, count);
    for (std::uint32_t p = 0; p < count; ++p) diagram->insert(p, start[p]);
  }
  ParticleVoronoi& voronoi = *diagram;
  ProgressLine progress("spread", max_sweeps, quiet);
  std::unordered_set<std::uint64_t> seen = {positions_hash(outcome.positions)};
  // Every particle decides in the first sweep; after it, only one whose
  // region a move has reshaped since its last decision (a particle that
  // moves reshapes its own), or one the farthest vertex is now far enough
  // to draw away: farther than its gap, which is as at its last decision,
  // plus min_gain. Any other would find the same gap and no vertex it
  // would move to, and stay (but for fast marching's order-dependent
  // noise), so its two marches are spared: in the later sweeps a few per
  // cent of the particles move.
  std::vector<std::uint8_t> pending(count, 1);
  std::vector<double> last_spacing(count, std::numeric_limits<double>::infinity());
  const auto farthest_distance = [&] {
    const auto farthest = voronoi.farthest();
    return farthest ? voronoi.distance(*farthest) : 0.0f;
  };
  const auto mark_reshaped = [&] {
    for (const std::uint32_t q : voronoi.reshaped()) pending[q] = 1;
  };
  for (std::size_t sweep = 0; sweep < max_sweeps; ++sweep) {
    const auto started = std::chrono::steady_clock::now();
    SweepRecord record;
    record.min_spacing = std::numeric_limits<double>::infinity();
    double spacing_sum = 0;
    std::size_t spaced = 0;
    for (std::uint32_t p = 0; p < count; ++p) {
      if (pending[p] || farthest_distance() > last_spacing[p] + min_gain) {
        pending[p] = 0;
        ++record.visited;
        const VertexId here = *voronoi.vertex_of(p);
        voronoi.remove(p);
        const double spacing_here = voronoi.distance(here);
        // Another particle's vertex is at distance 0, so the farthest vertex
        // is free whenever it is farther than here.
        const auto farthest = voronoi.farthest();
        if (farthest && voronoi.distance(*farthest) > spacing_here + min_gain) {
          last_spacing[p] = voronoi.distance(*farthest);
          mark_reshaped();
          voronoi.insert(p, *farthest);
          mark_reshaped();
          ++record.moved;
        } else {
          voronoi.insert(p, here);
          last_spacing[p] = spacing_here;
        }
        outcome.positions[p] = *voronoi.vertex_of(p);
      }
      const double spacing = last_spacing[p];
      // +inf: alone in its component; left out of the spacing figures.
      if (spacing < std::numeric_limits<double>::infinity()) {
        record.min_spacing = std::min(record.min_spacing, spacing);
        spacing_sum += spacing;
        ++spaced;
      }
    }
    record.mean_spacing = spaced ? spacing_sum / double(spaced) : 0.0;
    if (spaced == 0) record.min_spacing = 0;
    record.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    outcome.sweeps.push_back(record);
    char detail[64];
    std::snprintf(detail, sizeof detail, "moved %zu", record.moved);
    progress.update(sweep + 1, detail);
    if (record.moved == 0) {
      outcome.converged = true;
      break;
    }
    // Back to a set of positions met before: the rest would repeat.
    if (!seen.insert(positions_hash(outcome.positions)).second) {
      outcome.cycled = true;
      break;
    }
    if (sweep > 0 && record.mean_spacing < outcome.sweeps[sweep - 1].mean_spacing + stall_gain) {
      outcome.stalled = true;
      break;
    }
  }
  progress.finish(outcome.converged ? "converged"
                  : outcome.cycled  ? "settled in a cycle"
                  : outcome.stalled ? "stalled"
                                    : "sweep limit reached");
  return outcome;
}

}  // namespace meshparticles
