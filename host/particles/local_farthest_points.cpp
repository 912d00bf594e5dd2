#include "particles/local_farthest_points.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "particles/surface_voronoi.hpp"

namespace meshparticles {

namespace {

// A move goes at most this many hexagonal spacings: the centre sought is
// within the particle's own cavity, and a longer step would leave the
// surface its neighbours' straight lines describe.
constexpr double kLongestMove = 0.5;
// A particle's gap is measured along the surface up to its estimate plus
// this many spacings (the estimate is a straight line or a path through the
// diagram: within a few per cent where it is not across a fold).
constexpr double kGapMargin = 0.1;
// Neighbours this many steps apart in the diagram's graph are estimated
// too: a move of at most kLongestMove cannot come near a particle farther
// out than that without passing one of these.
constexpr int kReachSteps = 3;
// A particle two or more steps away whose path through the diagram is over
// this many times the straight line is across a thin part or a fold: its
// distance is taken as that path over the same factor, not the straight
// line through the air.
constexpr double kThroughAir = 2.0;

struct Neighbour {
  std::uint32_t particle = 0;
  double stretch = 1;  // the distance estimated is stretch x the straight line
};

// Per particle, the particles within kReachSteps steps of the diagram's
// graph with their stretch: the neighbours (regions touching) first.
struct NeighbourLists {
  std::vector<std::vector<Neighbour>> near;    // regions touching
  std::vector<std::vector<Neighbour>> around;  // 2 to kReachSteps steps away
};

using PathsFrom = std::vector<std::vector<std::pair<std::uint32_t, double>>>;

// The particles within kReachSteps steps of i and the shortest path to
// each through the graph, `along` (+inf between calls) as the scratch.
void reachable(std::uint32_t i, const PathsFrom& paths, std::vector<double>& along,
               std::vector<std::uint32_t>& reached) {
  std::vector<std::uint32_t> frontier{i}, next;
  along[i] = 0;
  reached.assign(1, i);
  for (int step = 0; step < kReachSteps; ++step) {
    next.clear();
    for (const std::uint32_t k : frontier) {
      for (const auto& [l, length] : paths[k]) {
        if (std::isinf(along[l])) {
          reached.push_back(l);
          next.push_back(l);
        }
        along[l] = std::min(along[l], along[k] + length);
      }
    }
    frontier.swap(next);
  }
}

NeighbourLists neighbour_lists(const SurfaceMesh& mesh, const SurfaceVoronoi& cells,
                               const std::vector<SurfaceLocation>& points) {
  NeighbourLists lists;
  lists.near.resize(points.size());
  lists.around.resize(points.size());
  PathsFrom paths(points.size());
  for (const SurfacePath& path : cells.neighbour_paths(mesh)) {
    const double straight = distance(points[path.a].at, points[path.b].at);
    const double stretch = straight > 0 ? std::max(1.0, path.length / straight - kPathSlack) : 1.0;
    lists.near[path.a].push_back({path.b, stretch});
    lists.near[path.b].push_back({path.a, stretch});
    paths[path.a].emplace_back(path.b, path.length);
    paths[path.b].emplace_back(path.a, path.length);
  }
  std::vector<double> along(points.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> reached;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    reachable(i, paths, along, reached);
    for (const Neighbour& k : lists.near[i]) along[k.particle] = -along[k.particle];  // marked: listed already
    for (const std::uint32_t k : reached) {
      if (k != i && along[k] > 0) {
        const double straight = distance(points[i].at, points[k].at);
        const double stretch =
            straight > 0 && along[k] > kThroughAir * straight ? along[k] / kThroughAir / straight : 1.0;
        lists.around[i].push_back({k, stretch});
      }
      along[k] = std::numeric_limits<double>::infinity();
    }
  }
  return lists;
}

// The estimated smallest distance from `at` to the particles listed for i.
double estimated_gap(const Vec3& at, std::uint32_t i, const NeighbourLists& lists,
                     const std::vector<SurfaceLocation>& points) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto* list : {&lists.near[i], &lists.around[i]}) {
    for (const Neighbour& k : *list) smallest = std::min(smallest, k.stretch * distance(at, points[k.particle].at));
  }
  return smallest;
}

// Each particle's triangle's corners, by vertex: whom a march from a point meets.
class CornerIndex {
 public:
  CornerIndex(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& points)
      : mesh_(mesh), at_(mesh.vertex_count()) {
    for (std::uint32_t i = 0; i < points.size(); ++i) add(i, points[i].triangle);
  }
  void move(std::uint32_t particle, std::uint32_t from, std::uint32_t to) {
    for (const VertexId c : mesh_.triangles()[from]) std::erase(at_[c], particle);
    add(particle, to);
  }
  const std::vector<std::uint32_t>& at(VertexId v) const { return at_[v]; }

 private:
  void add(std::uint32_t particle, std::uint32_t triangle) {
    for (const VertexId c : mesh_.triangles()[triangle]) at_[c].push_back(particle);
  }
  const SurfaceMesh& mesh_;
  std::vector<std::vector<std::uint32_t>> at_;
};

// What a move is judged by: the distance along the surface from `from` to
// the nearest particle other than i, marched from its triangle's corners
// up to `radius` (returned where none is nearer). A particle is reached
// through its triangle's corners, at d(corner) + |corner - particle|.
class SurfaceGap {
 public:
  SurfaceGap(const SurfaceMesh& mesh, const GeodesicSolver& solver) : mesh_(mesh), solver_(solver) {}
  // `reach`: the farthest any particle is from a corner of its triangle
  // (a particle nearer than `radius` has a corner within radius + reach).
  double operator()(const SurfaceLocation& from, std::uint32_t i, double radius, double reach,
                    const CornerIndex& corners, const std::vector<SurfaceLocation>& points) {
    const Triangle& t = mesh_.triangles()[from.triangle];
    const auto& p = mesh_.positions();
    const double starts[3] = {distance(from.at, p[t[0]]), distance(from.at, p[t[1]]), distance(from.at, p[t[2]])};
    solver_.solve_ball_from(t, starts, radius + reach, scratch_, within_);
    double nearest = radius;
    for (const auto& [v, d] : within_) {
      for (const std::uint32_t k : corners.at(v)) {
        if (k != i) nearest = std::min(nearest, double(d) + distance(p[v], points[k].at));
      }
    }
    return nearest;
  }

 private:
  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  SolverScratch scratch_;
  std::vector<std::pair<VertexId, float>> within_;
};

// The centre of the circle through a, b and c in the plane; false when they are on a line.
bool circumcentre(const double* a, const double* b, const double* c, double& x, double& y) {
  const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
  if (std::abs(d) < 1e-300) return false;
  const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
  x = (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d;
  y = (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d;
  return true;
}

// The point of i's tangent plane, within `longest` of it, where its
// estimated gap is widest: of the centres of the circles through three of
// its plain neighbours (in the plane, the corners of the Voronoi diagram of
// its neighbours: where the largest empty circle of its cavity is centred).
Vec3 widest_centre(const SurfaceWalk& walk, const SurfaceLocation& p, std::uint32_t i, const NeighbourLists& lists,
                   const std::vector<SurfaceLocation>& points, double longest, double& widest) {
  const Vec3 n = walk.normal(p.triangle);
  const Vec3 e1 = walk.first_edge_direction(p.triangle);
  const Vec3 e2 = cross(n, e1);
  std::vector<std::array<double, 2>> plane;
  for (const Neighbour& k : lists.near[i]) {
    if (k.stretch > 1) continue;  // across a fold: no straight centre with it
    const Vec3 to = points[k.particle].at - p.at;
    plane.push_back({dot(to, e1), dot(to, e2)});
  }
  Vec3 best = p.at;
  for (std::size_t a = 0; a < plane.size(); ++a) {
    for (std::size_t b = a + 1; b < plane.size(); ++b) {
      for (std::size_t c = b + 1; c < plane.size(); ++c) {
        double x = 0, y = 0;
        if (!circumcentre(plane[a].data(), plane[b].data(), plane[c].data(), x, y)) continue;
        if (x * x + y * y > longest * longest) continue;
        const Vec3 at = p.at + x * e1 + y * e2;
        const double gap = estimated_gap(at, i, lists, points);
        if (gap > widest) {
          widest = gap;
          best = at;
        }
      }
    }
  }
  return best;
}

// Each particle's largest distance to a vertex of its own region.
std::vector<double> region_reach(const SurfaceVoronoi& cells, std::size_t count) {
  std::vector<double> reach(count, 0.0);
  for (std::size_t v = 0; v < cells.owner.size(); ++v) {
    const std::uint32_t owner = cells.owner[v];
    if (owner != SurfaceVoronoi::kNoPoint) reach[owner] = std::max(reach[owner], double(cells.distance[v]));
  }
  return reach;
}

// The farthest `p` is from a corner of its triangle.
double corner_offset(const SurfaceMesh& mesh, const SurfaceLocation& p) {
  double offset = 0;
  for (const VertexId c : mesh.triangles()[p.triangle]) offset = std::max(offset, distance(p.at, mesh.positions()[c]));
  return offset;
}

// The evening's state between sweeps, and one particle's move.
class Evening {
 public:
  Evening(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> points,
          const EveningLimits& limits)
      : mesh_(mesh), solver_(solver), walk_(mesh), gap_(mesh, solver), limits_(limits), points_(std::move(points)),
        corners_(mesh, points_), visit_(points_.size(), 1) {
    find_neighbours();
  }

  // One sweep over the particles to visit; its record.
  EveningSweep sweep() {
    const auto started = std::chrono::steady_clock::now();
    EveningSweep record;
    record.cover = cells_.cover();
    // A move of length m leaves the mover's old region within its reach
    // plus m of it: the covering radius stays within the limit when that does.
    const std::vector<double> reach = region_reach(cells_, points_.size());
    corner_reach_ = 0;
    for (const SurfaceLocation& p : points_) corner_reach_ = std::max(corner_reach_, corner_offset(mesh_, p));
    std::vector<char> moved(points_.size(), 0);
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (visit_[i] && try_move(i, lists_, reach[i])) moved[i] = 1;
    }
    record.moved = std::size_t(std::count(moved.begin(), moved.end(), 1));
    find_neighbours();
    summarize(moved, record);
    record.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return record;
  }

  EveningOutcome outcome(std::vector<EveningSweep> sweeps) {
    return {std::move(points_), std::move(sweeps), cells_.cover()};
  }

 private:
  // Moves particle i to the widest centre of its cavity where that widens
  // its own gap along the surface and holds the cover; whether it moved.
  bool try_move(std::uint32_t i, const NeighbourLists& lists, double reach) {
    SurfaceLocation& p = points_[i];
    const double before = estimated_gap(p.at, i, lists, points_);
    if (!std::isfinite(before) || norm(walk_.normal(p.triangle)) == 0) return false;
    double widest = before;
    const Vec3 centre = widest_centre(walk_, p, i, lists, points_, kLongestMove * limits_.d_hex, widest);
    if (widest <= before + limits_.min_gain) return false;
    const SurfaceLocation there = walk_.walk(p.triangle, centre);
    if (reach + distance(there.at, p.at) > std::max(limits_.cover, reach)) return false;
    if (estimated_gap(there.at, i, lists, points_) <= before + limits_.min_gain) return false;
    // Kept only where it widens the particle's own gap along the surface,
    // measured: straight lines and the diagram's paths misjudge folds.
    const double margin = std::max(corner_reach_, corner_offset(mesh_, there));
    const double was = gap_(p, i, before + kGapMargin * limits_.d_hex, margin, corners_, points_);
    const double wanted = was + limits_.min_gain;
    if (gap_(there, i, wanted, margin, corners_, points_) < wanted) return false;
    corners_.move(i, p.triangle, there.triangle);
    p = there;
    corner_reach_ = margin;
    return true;
  }

  // The diagram of the particles where they are, and their neighbours in it.
  void find_neighbours() {
    cells_ = surface_voronoi(mesh_, solver_, points_, scratch_);
    lists_ = neighbour_lists(mesh_, cells_, points_);
  }

  // The record's spacings over the new diagram, and who to visit next:
  // those that moved or whose neighbours did (no other can have gained).
  void summarize(const std::vector<char>& moved, EveningSweep& record) {
    const NeighbourLists& after = lists_;
    double sum = 0, smallest = std::numeric_limits<double>::infinity();
    std::size_t counted = 0;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      visit_[i] = moved[i];
      for (const Neighbour& k : after.near[i]) visit_[i] = visit_[i] || moved[k.particle];
      const double gap = estimated_gap(points_[i].at, i, after, points_);
      if (!std::isfinite(gap)) continue;
      sum += gap;
      smallest = std::min(smallest, gap);
      ++counted;
    }
    record.mean = counted ? sum / double(counted) : 0;
    record.smallest = counted ? smallest : 0;
  }

  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  const SurfaceWalk walk_;
  SurfaceGap gap_;
  const EveningLimits limits_;
  std::vector<SurfaceLocation> points_;
  CornerIndex corners_;
  std::vector<char> visit_;
  SolverScratch scratch_;
  SurfaceVoronoi cells_;
  NeighbourLists lists_;  // of cells_
  double corner_reach_ = 0;  // the largest corner_offset of any particle
};

}  // namespace

EveningOutcome even_out(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> points,
                        const EveningLimits& limits, bool quiet) {
  Evening evening(mesh, solver, std::move(points), limits);
  std::vector<EveningSweep> sweeps;
  ProgressLine progress("even", limits.max_sweeps, quiet);
  for (std::size_t sweep = 1; sweep <= limits.max_sweeps; ++sweep) {
    sweeps.push_back(evening.sweep());
    const EveningSweep& record = sweeps.back();
    progress.update(sweep, "smallest spacing " + format_number("%.4f", record.smallest / limits.d_hex) + " d_hex, " +
                               std::to_string(record.moved) + " moved");
    const bool stalled = sweeps.size() > 1 && record.mean - sweeps[sweeps.size() - 2].mean < limits.stall_gain;
    if (record.moved == 0 || stalled) break;
  }
  progress.finish();
  return evening.outcome(std::move(sweeps));
}

}  // namespace meshparticles
