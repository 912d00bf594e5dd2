#include "particles/hole_swap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "mesh/surface_walk.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/widest_hole.hpp"

namespace meshparticles {

namespace {

// A swap must lessen the shortfall by more than this: rounding is no gain.
constexpr double kLeastGain = 1e-9;
// Pairs are looked for within this many times the wanted spacing: farther
// ones count as that far (enough to tell a gain from a loss near the limit).
constexpr double kPairReach = 2;

// A set's two figures: its widest hole (a point of the surface between the
// vertices too, and its particle; its width as hole_width takes it) and its
// closest pair along the surface (and which two those are; 0 and 0 where no
// pair is within kPairReach spacings: particle 0 is then only one more
// mover tried).
struct Figures {
  double cover = 0;
  WidestHole hole;
  double smallest = std::numeric_limits<double>::infinity();
  std::uint32_t a = 0, b = 0;
};

Figures figures(const SurfaceMesh& mesh, const VertexTriangles& rings, const SurfaceVoronoi& diagram,
                const std::vector<SurfaceLocation>& points, const SurfaceNeighbours& surface, LookScratch& look,
                const HoleSwapLimits& limits) {
  Figures found;
  found.hole = widest_hole(mesh, rings, diagram, points, limits.hole_step);
  found.cover = hole_width(found.hole, diagram);
  const ClosestPair closest = closest_surface_pair(points, surface, kPairReach * limits.spacing, look);
  found.smallest = closest.spacing;
  found.a = closest.a;
  found.b = closest.b;
  return found;
}

// How far a set falls short of the limits, each figure relative to its own.
double shortfall(const Figures& set, const HoleSwapLimits& limits) {
  return std::max(0.0, 1 - set.smallest / limits.spacing) + std::max(0.0, set.cover / limits.cover - 1);
}

constexpr std::uint32_t kUnreached = std::numeric_limits<std::uint32_t>::max();

// A breadth-first walk of the neighbour graph from `from`, each ring in
// index order, out to `steps` steps or until `goal` is reached: the
// particles reached, in that order, and each one's step back towards
// `from` (kUnreached for the rest).
struct Walk {
  std::vector<std::uint32_t> reached;
  std::vector<std::uint32_t> back;
};

Walk walk_from(const std::vector<std::vector<std::uint32_t>>& neighbours, std::uint32_t from, std::size_t steps,
               std::uint32_t goal = kUnreached) {
  Walk walk{{from}, std::vector<std::uint32_t>(neighbours.size(), kUnreached)};
  walk.back[from] = from;
  std::size_t ring_begin = 0;
  for (std::size_t step = 0; step < steps && (goal == kUnreached || walk.back[goal] == kUnreached); ++step) {
    const std::size_t ring_end = walk.reached.size();
    if (ring_begin == ring_end) break;
    for (std::size_t k = ring_begin; k < ring_end; ++k) {
      for (const std::uint32_t next : neighbours[walk.reached[k]]) {
        if (walk.back[next] != kUnreached) continue;
        walk.back[next] = walk.reached[k];
        walk.reached.push_back(next);
      }
    }
    std::sort(walk.reached.begin() + std::ptrdiff_t(ring_end), walk.reached.end());
    ring_begin = ring_end;
  }
  return walk;
}

// The particles within `steps` steps of `from` on the neighbour graph, `from` first.
std::vector<std::uint32_t> within_steps(const std::vector<std::vector<std::uint32_t>>& neighbours, std::uint32_t from,
                                        std::size_t steps) {
  return walk_from(neighbours, from, steps).reached;
}

// The particles on a shortest path from `from` to `to` on the neighbour
// graph, both ends included; empty where none joins them. Ties go to the
// lowest index.
std::vector<std::uint32_t> shortest_path(const std::vector<std::vector<std::uint32_t>>& neighbours, std::uint32_t from,
                                         std::uint32_t to) {
  const Walk walk = walk_from(neighbours, to, neighbours.size(), from);
  if (walk.back[from] == kUnreached) return {};
  std::vector<std::uint32_t> path{from};
  while (path.back() != to) path.push_back(walk.back[path.back()]);
  return path;
}

// A set of places, its diagram and its figures.
struct Trial {
  std::vector<SurfaceLocation> points;
  SurfaceVoronoi diagram;
  Figures figures;
};

class Swapper {
 public:
  Swapper(const SurfaceMesh& mesh, const GeodesicSolver& solver, const SurfaceNeighbours& surface, LookScratch& look,
          const HoleSwapLimits& limits)
      : mesh_(mesh), solver_(solver), surface_(surface), look_(look), walk_(mesh), limits_(limits) {}

  Trial measured(std::vector<SurfaceLocation> points) {
    Trial trial{std::move(points), {}, {}};
    trial.diagram = surface_voronoi(mesh_, solver_, trial.points, scratch_);
    trial.figures = figures(mesh_, walk_.triangles_around(), trial.diagram, trial.points, surface_, look_, limits_);
    aim_at_vertices(trial);
    return trial;
  }

  // Where the diagram at the vertices reads a hole wider than widest_hole
  // found (hole_width takes the wider), the swaps aim at that vertex: its
  // owner's neighbours the movers, the vertex where a carry ends. Aimed at
  // widest_hole's point, no swap could narrow the width they are judged by
  // (FAUST's tr_reg_007 at n = 256 after 0.15.0's evening: its sampled
  // hole at the hands 0.91 spacings, its width 0.99 at a vertex of the
  // legs, 2 swaps and then none).
  void aim_at_vertices(Trial& trial) const {
    WidestHole& hole = trial.figures.hole;
    const std::vector<float>& distance = trial.diagram.distance;
    std::optional<VertexId> widest;
    for (VertexId v = 0; v < distance.size(); ++v) {
      if (trial.diagram.owner[v] == SurfaceVoronoi::kNoPoint || !std::isfinite(distance[v])) continue;
      if (!widest || distance[v] > distance[*widest]) widest = v;
    }
    if (!widest || !(double(distance[*widest]) > hole.away)) return;
    hole = {walk_.at_vertex(*widest), trial.diagram.owner[*widest], double(distance[*widest])};
  }

  // `points` with particle `mover` taken out and put at the vertex farthest
  // from the rest among the regions of `neighbourhood` (its own excluded);
  // none where no vertex there is reached, or where that vertex lies
  // nearer the rest than `closest` (the move could only be refused).
  std::optional<Trial> moved(const std::vector<SurfaceLocation>& points, std::uint32_t mover,
                             const std::vector<std::uint32_t>& neighbourhood, double closest) {
    std::vector<SurfaceLocation> rest = points;
    rest.erase(rest.begin() + mover);
    const SurfaceVoronoi without = surface_voronoi(mesh_, solver_, rest, scratch_);
    std::vector<char> near(points.size(), 0);
    for (const std::uint32_t k : neighbourhood) near[k] = 1;
    std::optional<VertexId> target;
    double farthest = -1;
    for (VertexId v = 0; v < without.distance.size(); ++v) {
      const std::uint32_t owner = without.owner[v];
      if (owner == SurfaceVoronoi::kNoPoint) continue;
      const std::uint32_t particle = owner < mover ? owner : owner + 1;  // its index among `points`
      if (!near[particle] || !(without.distance[v] > farthest)) continue;
      farthest = without.distance[v];
      target = v;
    }
    if (!target || farthest < closest) return std::nullopt;
    std::vector<SurfaceLocation> there = points;
    there[mover] = walk_.at_vertex(*target);
    return measured(std::move(there));
  }

  // `points` less the place of `path`'s first particle and with `hole` (a
  // point of the last one's region) added: each particle on the path takes
  // the next one's place and the last goes into the hole. As a set, the
  // first particle put into the hole however far off; carried so, each
  // moves by about a spacing and stays near where it is on other shapes.
  Trial carried(const std::vector<SurfaceLocation>& points, const std::vector<std::uint32_t>& path,
                const SurfaceLocation& hole) {
    std::vector<SurfaceLocation> there = points;
    for (std::size_t j = 0; j + 1 < path.size(); ++j) there[path[j]] = points[path[j + 1]];
    there[path.back()] = hole;
    return measured(std::move(there));
  }

 private:
  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  const SurfaceNeighbours& surface_;
  LookScratch& look_;
  const SurfaceWalk walk_;
  const HoleSwapLimits& limits_;
  SolverScratch scratch_;
};

}  // namespace

HoleSwapOutcome swap_into_holes(const SurfaceMesh& mesh, const GeodesicSolver& solver, const SurfaceNeighbours& surface,
                                LookScratch& look, std::vector<SurfaceLocation>& points, const HoleSwapLimits& limits) {
  HoleSwapOutcome outcome;
  if (points.size() < 3) return outcome;
  Swapper swapper(mesh, solver, surface, look, limits);
  Trial now = swapper.measured(std::move(points));  // each swap's start: the last one kept
  for (;;) {
    outcome.smallest = now.figures.smallest;
    outcome.cover = now.figures.cover;
    const double short_now = shortfall(now.figures, limits);
    if (outcome.swaps == limits.max_swaps || short_now <= 0) break;
    std::vector<std::vector<std::uint32_t>> neighbours(now.points.size());
    for (const SurfacePath& path : now.diagram.neighbour_paths(mesh)) {
      neighbours[path.a].push_back(path.b);
      neighbours[path.b].push_back(path.a);
    }
    const std::uint32_t hole_owner = now.figures.hole.owner;
    std::optional<Trial> best;
    double short_best = short_now - kLeastGain;
    const auto consider = [&](Trial trial) {
      const Figures& then = trial.figures;
      if (then.smallest < now.figures.smallest || then.cover > std::max(now.figures.cover, limits.cover)) return;
      const double short_then = shortfall(then, limits);
      if (short_then < short_best) {
        short_best = short_then;
        best = std::move(trial);
      }
    };
    std::vector<std::uint32_t> movers = within_steps(neighbours, hole_owner, limits.steps);
    movers.push_back(now.figures.a);
    movers.push_back(now.figures.b);
    std::sort(movers.begin(), movers.end());
    movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
    for (const std::uint32_t mover : movers) {
      std::vector<std::uint32_t> neighbourhood = within_steps(neighbours, mover, limits.steps);
      neighbourhood.erase(neighbourhood.begin());  // the mover's own region is no place to go
      std::optional<Trial> trial = swapper.moved(now.points, mover, neighbourhood, now.figures.smallest);
      if (trial) consider(std::move(*trial));
    }
    // Where no local move helps and the pair is closer than `carry_below`
    // (or the hole wider than `carry_above`), its particles carried into the
    // widest hole, however far.
    if (!best && (now.figures.smallest < limits.carry_below || now.figures.cover > limits.carry_above)) {
      for (const std::uint32_t mover : {now.figures.a, now.figures.b}) {
        const std::vector<std::uint32_t> path = shortest_path(neighbours, mover, hole_owner);
        if (!path.empty()) consider(swapper.carried(now.points, path, now.figures.hole.at));
      }
    }
    if (!best) break;
    now = std::move(*best);
    ++outcome.swaps;
  }
  points = std::move(now.points);
  return outcome;
}

}  // namespace meshparticles
