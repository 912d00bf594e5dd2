#include "particles/farthest_point_optimization.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <unordered_set>

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
                                       double stall_gain, bool quiet) {
  SpreadOutcome outcome;
  outcome.positions = start;
  const auto count = std::uint32_t(start.size());
  if (max_sweeps == 0 || count < 2) {
    outcome.converged = count < 2;
    return outcome;
  }
  ParticleVoronoi voronoi(mesh, solver, count);
  for (std::uint32_t p = 0; p < count; ++p) voronoi.insert(p, start[p]);
  ProgressLine progress("spread", max_sweeps, quiet);
  std::unordered_set<std::uint64_t> seen = {positions_hash(outcome.positions)};
  for (std::size_t sweep = 0; sweep < max_sweeps; ++sweep) {
    const auto started = std::chrono::steady_clock::now();
    SweepRecord record;
    record.min_spacing = std::numeric_limits<double>::infinity();
    double spacing_sum = 0;
    std::size_t spaced = 0;
    for (std::uint32_t p = 0; p < count; ++p) {
      const VertexId here = *voronoi.vertex_of(p);
      voronoi.remove(p);
      const double spacing_here = voronoi.distance(here);
      VertexId chosen = here;
      double spacing = spacing_here;
      // Another particle's vertex is at distance 0, so the farthest vertex
      // is free whenever it is farther than here.
      if (const auto farthest = voronoi.farthest(); farthest && voronoi.distance(*farthest) > spacing_here + min_gain) {
        chosen = *farthest;
        spacing = voronoi.distance(chosen);
        ++record.moved;
      }
      voronoi.insert(p, chosen);
      outcome.positions[p] = chosen;
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
