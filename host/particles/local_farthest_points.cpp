#include "particles/local_farthest_points.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/elapsed.hpp"
#include "common/parallel_for.hpp"
#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "geodesics/distance_in_triangle.hpp"
#include "geodesics/memory_guard.hpp"
#include "particles/surface_voronoi.hpp"

namespace meshparticles {

namespace {

// A move goes all the way to the centre of the largest empty circle of the
// particle's neighbours (farthest-point optimization's full jump); only a
// centre farther than this many hexagonal spacings, the circle of three
// neighbours nearly on a line, is not one.
constexpr double kLongestMove = 1.5;
// Neighbours whose stretch is over this are across a fold: no circle
// through them in the tangent plane is a centre (a curved surface's
// neighbours stretch a few per cent: with 1, a particle on a curved part
// of cow lost 3 of its 7 neighbours' circles).
constexpr double kFoldStretch = 1.3;
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
// Sweeps stop once this many in a row have each raised the mean spacing by
// under the stall gain: a sweep of few moves can open room for the next
// (measured on dino and cow at n = 1,024: 5 in a row gave the same rho as
// 2, in 13 sweeps against 9 or 10).
constexpr std::size_t kStallSweeps = 2;
// A move's length along the surface is taken as at most this many times
// its straight length where the cover is bounded without a march.
constexpr double kMoveSlack = 1.1;
// What a march's scratch holds per vertex (SolverScratch::fit: accepted,
// heap_slot, origin, distances; SurfaceGap's reached).
constexpr std::uint64_t kScratchBytesPerVertex = 1 + 4 + 4 + 8 + 4;

struct Neighbour {
  std::uint32_t particle = 0;
  double stretch = 1;  // the distance estimated is stretch x the straight line
  Vec3 crossing{};     // near lists only: where the shortest path between the two regions crosses their border
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
                               const std::vector<SurfaceLocation>& points, unsigned threads) {
  NeighbourLists lists;
  lists.near.resize(points.size());
  lists.around.resize(points.size());
  PathsFrom paths(points.size());
  for (const SurfacePath& path : cells.neighbour_paths(mesh)) {
    const double straight = distance(points[path.a].at, points[path.b].at);
    const double stretch = straight > 0 ? std::max(1.0, path.length / straight - kPathSlack) : 1.0;
    lists.near[path.a].push_back({path.b, stretch, path.crossing});
    lists.near[path.b].push_back({path.a, stretch, path.crossing});
    paths[path.a].emplace_back(path.b, path.length);
    paths[path.b].emplace_back(path.a, path.length);
  }
  // Each particle's list from its own paths: one thread's scratch per slot.
  std::vector<std::vector<double>> alongs(threads);
  std::vector<std::vector<std::uint32_t>> reacheds(threads);
  for_each_with_slot(points.size(), threads, [&](std::size_t particle, unsigned slot) {
    const auto i = std::uint32_t(particle);
    std::vector<double>& along = alongs[slot];
    std::vector<std::uint32_t>& reached = reacheds[slot];
    if (along.empty()) along.assign(points.size(), std::numeric_limits<double>::infinity());
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
  });
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
// the nearest particle other than i, up to `radius` (returned where none is
// nearer), by a march from its triangle's corners. A particle is reached
// through its triangle, from the corners the march reached
// (distance_in_triangle; one in `from`'s own triangle in a straight line).
// A march that stops at `radius` may read a particle near its edge through
// one corner, or not at all: too far, never nearer than a longer march
// reads it. The gap a particle has is read so (at worst its move must beat
// too much). The gap it would have is read by a march one longest edge
// further (`whole`), which reaches every corner of any particle nearer
// than `radius`: a move back and forth each sweep is then not possible (it
// was, bull at 64: one particle until the 40th sweep).
class SurfaceGap {
 public:
  SurfaceGap(const SurfaceMesh& mesh, const GeodesicSolver& solver, double longest_edge)
      : mesh_(mesh), solver_(solver), longest_edge_(longest_edge) {}
  // `read`: every vertex whose particles it looked at is appended (a
  // particle moving to a triangle with no corner among them stays farther
  // than `radius`).
  double operator()(const SurfaceLocation& from, std::uint32_t i, double radius, const CornerIndex& corners,
                    const std::vector<SurfaceLocation>& points, std::vector<VertexId>& read, bool whole = false) {
    const Triangle& t = mesh_.triangles()[from.triangle];
    const auto& p = mesh_.positions();
    const double starts[3] = {distance(from.at, p[t[0]]), distance(from.at, p[t[1]]), distance(from.at, p[t[2]])};
    solver_.solve_ball_from(t, starts, whole ? radius + longest_edge_ : radius, scratch_, within_);
    if (reached_.empty()) reached_.assign(mesh_.vertex_count(), kUnreached);  // on first use, as the scratch
    for (const auto& [v, d] : within_) reached_[v] = d;
    double nearest = radius;
    for (const auto& [v, d] : within_) {
      read.push_back(v);
      for (const std::uint32_t k : corners.at(v)) {
        if (k != i && first_reached(points[k].triangle) == v) nearest = std::min(nearest, distance_to(from, points[k]));
      }
    }
    for (const auto& [v, d] : within_) reached_[v] = kUnreached;
    return nearest;
  }

 private:
  static constexpr float kUnreached = std::numeric_limits<float>::infinity();

  // A particle is read once, at the first of its triangle's corners the march reached.
  VertexId first_reached(std::uint32_t triangle) const {
    const Triangle& t = mesh_.triangles()[triangle];
    return !std::isinf(reached_[t[0]]) ? t[0] : !std::isinf(reached_[t[1]]) ? t[1] : t[2];
  }

  double distance_to(const SurfaceLocation& from, const SurfaceLocation& to) const {
    if (to.triangle == from.triangle) return distance(from.at, to.at);
    const Triangle& t = mesh_.triangles()[to.triangle];
    const auto& p = mesh_.positions();
    return distance_in_triangle({p[t[0]], p[t[1]], p[t[2]]}, {reached_[t[0]], reached_[t[1]], reached_[t[2]]}, to.at);
  }

  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  const double longest_edge_;
  SolverScratch scratch_;
  std::vector<std::pair<VertexId, float>> within_;
  std::vector<float> reached_;  // per vertex: the march's distance while a gap is read, else +inf
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

// Where neighbour `q` stands in the tangent plane (e1, e2) at `p`: at its
// straight distance, in the direction of `crossing`, where the shortest
// path to it leaves p's region. Its projection would do on a flat part;
// where the surface bends away within a spacing (a thin part, a tight
// curve) the projection is short and can point the wrong way, and the
// circles' centres miss the widest gap (0.15.0; 45 corpus runs: rho median
// 0.830 -> 0.840, higher on 21, lower on 2). At the path's length instead
// of the straight one, a strip folded back on itself lost 5% of its
// smallest spacing.
std::array<double, 2> unrolled(const Vec3& p, const Vec3& e1, const Vec3& e2, const Vec3& q, const Vec3& crossing) {
  const Vec3 to = q - p;
  const Vec3 out = crossing - p;
  const double x = dot(out, e1), y = dot(out, e2);
  const double across = std::hypot(x, y);
  if (across == 0) return {dot(to, e1), dot(to, e2)};  // the crossing is at p: its projection
  const double scale = norm(to) / across;
  return {x * scale, y * scale};
}

// The point of the surface where i's estimated gap is widest, of the
// centres of the circles through three of its plain neighbours in its
// tangent plane (in the plane, the corners of the Voronoi diagram of its
// neighbours: where the largest empty circle of its cavity is centred),
// each within `longest` of it and walked onto the surface, judged there;
// `p` itself where none is wider than `widest` (its gap where it stands).
SurfaceLocation widest_centre(const SurfaceWalk& walk, const SurfaceLocation& p, std::uint32_t i,
                              const NeighbourLists& lists, const std::vector<SurfaceLocation>& points, double longest,
                              double& widest) {
  const Vec3 n = walk.normal(p.triangle);
  const Vec3 e1 = walk.first_edge_direction(p.triangle);
  const Vec3 e2 = cross(n, e1);
  std::vector<std::array<double, 2>> plane;
  for (const Neighbour& k : lists.near[i]) {
    if (k.stretch > kFoldStretch) continue;  // across a fold: no straight centre with it
    plane.push_back(unrolled(p.at, e1, e2, points[k.particle].at, k.crossing));
  }
  SurfaceLocation best = p;
  for (std::size_t a = 0; a < plane.size(); ++a) {
    for (std::size_t b = a + 1; b < plane.size(); ++b) {
      for (std::size_t c = b + 1; c < plane.size(); ++c) {
        double x = 0, y = 0;
        if (!circumcentre(plane[a].data(), plane[b].data(), plane[c].data(), x, y)) continue;
        if (x * x + y * y > longest * longest) continue;
        const Vec3 at = p.at + x * e1 + y * e2;
        // On a curved part the surface point is nearer i's neighbours than
        // the plane's: judged where the particle would stand.
        if (estimated_gap(at, i, lists, points) <= widest) continue;
        const SurfaceLocation walked = walk.walk(p.triangle, at);
        const double gap = estimated_gap(walked.at, i, lists, points);
        if (gap > widest) {
          widest = gap;
          best = walked;
        }
      }
    }
  }
  return best;
}

// What a particle's move is judged against, read only while proposals are
// computed: the state as the moves before them left it.
struct EveningView {
  const SurfaceMesh& mesh;
  const SurfaceWalk& walk;
  const EveningLimits& limits;
  const NeighbourLists& lists;
  const std::vector<SurfaceLocation>& points;
  const CornerIndex& corners;
};

// One particle's move as proposed: where to, and what it read.
struct Proposal {
  bool move = false;      // the widest centre widens its own gap along the surface
  SurfaceLocation there;  // where to, when it does
  // The vertices whose particles the marches looked at (a particle moved
  // from or to a triangle of one of them changes the proposal).
  std::vector<VertexId> read;
};

// Particle i's move, a function of i and the state `view` alone (`gap`
// brings the march's scratch): to the widest centre of its cavity
// (widest_centre) where that widens its own gap along the surface, measured
// by two marches (straight lines and the diagram's paths misjudge folds).
// The cover is judged at the commit (Evening::covered_after_move). One
// work-item per particle, as an OpenCL kernel would have it.
void propose_move(std::uint32_t i, const EveningView& view, SurfaceGap& gap, Proposal& proposal) {
  proposal.move = false;
  proposal.read.clear();
  const SurfaceLocation& p = view.points[i];
  const double before = estimated_gap(p.at, i, view.lists, view.points);
  if (!std::isfinite(before) || norm(view.walk.normal(p.triangle)) == 0) return;
  const EveningLimits& limits = view.limits;
  double widest = before;
  const SurfaceLocation there =
      widest_centre(view.walk, p, i, view.lists, view.points, kLongestMove * limits.d_hex, widest);
  if (widest <= before + limits.min_gain) return;
  const double was = gap(p, i, before + kGapMargin * limits.d_hex, view.corners, view.points, proposal.read);
  const double wanted = was + limits.min_gain;
  if (gap(there, i, wanted, view.corners, view.points, proposal.read, true) < wanted) return;
  proposal.move = true;
  proposal.there = there;
}

// The particles to visit in sets whose moves cannot meet: a greedy
// colouring by index of the graph joining each particle to those within
// kReachSteps steps (its lists, all a proposal reads of others' positions).
// Sets in colour order, each in index order.
std::vector<std::vector<std::uint32_t>> independent_sets(const NeighbourLists& lists, const std::vector<char>& visit) {
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<std::uint32_t> colour(visit.size(), kNone);
  std::vector<std::vector<std::uint32_t>> sets;
  std::vector<char> taken;
  for (std::uint32_t i = 0; i < visit.size(); ++i) {
    if (!visit[i]) continue;
    taken.assign(sets.size() + 1, 0);
    for (const auto* list : {&lists.near[i], &lists.around[i]}) {
      for (const Neighbour& k : *list) {
        if (colour[k.particle] != kNone) taken[colour[k.particle]] = 1;
      }
    }
    colour[i] = std::uint32_t(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    if (colour[i] == sets.size()) sets.emplace_back();
    sets[colour[i]].push_back(i);
  }
  return sets;
}

// The evening's state between sweeps, and one particle's move.
class Evening {
 public:
  Evening(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> points,
          const EveningLimits& limits, unsigned threads, DeviceSurfaceVoronoi* device)
      : mesh_(mesh), solver_(solver), device_(device), walk_(mesh), limits_(limits), threads_(std::max(1u, threads)),
        points_(std::move(points)), corners_(mesh, points_), visit_(points_.size(), 1),
        moved_in_set_(points_.size(), 0), stamp_(mesh.vertex_count(), 0) {
    const double longest = longest_edge(mesh);
    for (unsigned k = 0; k < threads_; ++k) gaps_.emplace_back(mesh, solver, longest);
    find_neighbours();
  }

  // One sweep over the particles to visit; its record. The particles go in
  // independent sets (independent_sets): each set's moves are proposed at
  // once against the state the sets before it left (propose_move, on
  // threads_ threads), then committed in index order, each after its cover
  // check. A proposal that read what a commit of its own set changed (a
  // particle of its lists moved, or one moved from or to a triangle of a
  // vertex its marches read: a colouring by graph steps does not bound the
  // marches) is computed again at its commit. So the result is that of
  // visiting the particles one by one in the sets' order, whatever the
  // number of threads.
  EveningSweep sweep() {
    const auto started = std::chrono::steady_clock::now();
    EveningSweep record;
    record.cover = cells_.cover();
    std::vector<char> moved(points_.size(), 0);
    for (const std::vector<std::uint32_t>& set : independent_sets(lists_, visit_)) {
      ++set_stamp_;
      if (proposals_.size() < set.size()) proposals_.resize(set.size());
      const EveningView view{mesh_, walk_, limits_, lists_, points_, corners_};
      for_each_with_slot(set.size(), threads_,
                [&](std::size_t k, unsigned slot) { propose_move(set[k], view, gaps_[slot], proposals_[k]); });
      for (std::size_t k = 0; k < set.size(); ++k) {
        const std::uint32_t i = set[k];
        Proposal& proposal = proposals_[k];
        if (read_a_commit(i, proposal)) {
          const EveningView now{mesh_, walk_, limits_, lists_, points_, corners_};
          propose_move(i, now, gaps_[0], proposal);
        }
        const Vec3 was = points_[i].at;
        if (proposal.move && commit(i, proposal.there)) {
          moved[i] = 1;
          record.longest = std::max(record.longest, distance(was, points_[i].at));
        }
      }
    }
    record.moved = std::size_t(std::count(moved.begin(), moved.end(), 1));
    find_neighbours(&moved);
    summarize(moved, record);
    record.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return record;
  }

  EveningOutcome outcome(std::vector<EveningSweep> sweeps) {
    if (device_) {
      diagrams_.device = device_->device_name();
      diagrams_.rounds = device_->statistics().rounds;
    }
    return {std::move(points_), std::move(sweeps), cells_.cover(), diagrams_};
  }

 private:
  // Whether i's proposal read what a commit of its own set has changed since.
  bool read_a_commit(std::uint32_t i, const Proposal& proposal) const {
    for (const auto* list : {&lists_.near[i], &lists_.around[i]}) {
      for (const Neighbour& k : *list) {
        if (moved_in_set_[k.particle] == set_stamp_) return true;
      }
    }
    return std::any_of(proposal.read.begin(), proposal.read.end(),
                       [&](VertexId v) { return stamp_[v] == set_stamp_; });
  }

  // Moves i to `there` where that holds the cover; whether it moved.
  bool commit(std::uint32_t i, const SurfaceLocation& there) {
    if (!covered_after_move(i, there)) return false;
    SurfaceLocation& p = points_[i];
    for (const std::uint32_t triangle : {p.triangle, there.triangle}) {
      for (const VertexId c : mesh_.triangles()[triangle]) stamp_[c] = set_stamp_;
    }
    moved_in_set_[i] = set_stamp_;
    corners_.move(i, p.triangle, there.triangle);
    p = there;
    return true;
  }

  // The diagram of the particles where they are, and their neighbours in
  // it. After a sweep, the last diagram brought up to date where particles
  // `moved` (update_surface_voronoi, or on the device its update): later
  // sweeps move a few of them (man at n = 4,096: 3,415 in the first, 190
  // in the tenth), and anew each diagram was two fifths of the evening
  // there.
  void find_neighbours(const std::vector<char>* moved = nullptr) {
    const auto started = std::chrono::steady_clock::now();
    if (moved && device_) {
      device_->update(points_, *moved, cells_);
    } else if (moved) {
      update_surface_voronoi(mesh_, solver_, points_, *moved, cells_, scratch_);
    } else if (device_) {
      cells_ = device_->diagram(points_);
    } else {
      cells_ = surface_voronoi(mesh_, solver_, points_, scratch_);
    }
    diagrams_.seconds += seconds_since(started);
    ++diagrams_.count;
    lists_ = neighbour_lists(mesh_, cells_, points_, threads_);
    nearest_ = cells_.distance;
    owner_ = cells_.owner;
    region_.assign(points_.size(), {});
    for (VertexId v = 0; v < owner_.size(); ++v) {
      if (owner_[v] != SurfaceVoronoi::kNoPoint) region_[owner_[v]].push_back(v);
    }
  }

  // Whether moving i to `there` leaves every vertex within limits_.cover of
  // a particle, on the diagram as the sweep's moves have left it (nearest_,
  // owner_): the region i holds is refilled from its rim by the particles
  // around it (one march from the rim, each rim vertex from its own
  // particle, as particle_voronoi refills a region), and a march from
  // `there` takes what is nearer to it. Where the move holds the cover the
  // diagram is left updated for it, else as it was.
  bool covered_after_move(std::uint32_t i, const SurfaceLocation& there) {
    std::vector<VertexId>& mine = region_[i];
    std::erase_if(mine, [&](VertexId v) { return owner_[v] != i; });
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    // Where every vertex of the region stays within the limit of i even
    // after the move (its distance plus the move, the move's straight
    // length widened by kMoveSlack for the surface's bends), no march: the
    // region stays i's, each distance raised by that much.
    const double move = kMoveSlack * distance(there.at, points_[i].at);
    float reach = 0;
    for (const VertexId v : mine) reach = std::max(reach, nearest_[v]);
    if (reach + move <= limits_.cover) {
      for (const VertexId v : mine) nearest_[v] = float(nearest_[v] + move);
      return true;
    }
    undo_.clear();
    for (const VertexId v : mine) {
      undo_.push_back({v, nearest_[v], owner_[v]});
      nearest_[v] = std::numeric_limits<float>::infinity();
      owner_[v] = SurfaceVoronoi::kNoPoint;
    }
    rim_.clear();
    rim_sources_.clear();
    for (const VertexId v : mine) {
      for (const VertexId w : mesh_.one_ring(v)) {
        if (owner_[w] != SurfaceVoronoi::kNoPoint) {
          rim_.push_back(w);
          rim_sources_.push_back(owner_[w]);
        }
      }
    }
    // i's new triangle's corners join the rim as i's own sources, at their
    // straight distance from where it goes, where that is nearer: one
    // march fills the region from the particles around it and from i where
    // it goes, with the rules of surface_voronoi's (a vertex measured from
    // neighbours of one source only), so the cover judged here is the one
    // the next sweep's diagram finds.
    const Triangle& t = mesh_.triangles()[there.triangle];
    for (const VertexId c : t) {
      const auto d = float(distance(there.at, mesh_.positions()[c]));
      if (d >= nearest_[c]) continue;
      undo_.push_back({c, nearest_[c], owner_[c]});
      nearest_[c] = d;
      owner_[c] = i;
      rim_.push_back(c);
      rim_sources_.push_back(i);
    }
    solver_.lower_nearest_from(rim_, rim_sources_, nearest_, scratch_, lowered_, lowered_sources_, &lowered_was_);
    lowered_owners_.clear();
    for (std::size_t k = 0; k < lowered_.size(); ++k) {
      lowered_owners_.push_back(owner_[lowered_[k]]);
      owner_[lowered_[k]] = lowered_sources_[k];
    }
    const double limit = limits_.cover;
    bool covered = true;
    for (const VertexId v : mine) covered = covered && nearest_[v] <= limit;
    if (!covered) {
      // What i's march reached is undone; what the others' reached
      // outside i's region stays (a shorter path to a particle: true
      // either way), and their regions list it.
      for (std::size_t k = lowered_.size(); k-- > 0;) {
        if (lowered_sources_[k] != i) continue;
        nearest_[lowered_[k]] = lowered_was_[k];
        owner_[lowered_[k]] = lowered_owners_[k];
      }
      for (std::size_t k = undo_.size(); k-- > 0;) {
        nearest_[undo_[k].vertex] = undo_[k].nearest;
        owner_[undo_[k].vertex] = undo_[k].owner;
      }
      for (std::size_t k = 0; k < lowered_.size(); ++k) {
        if (owner_[lowered_[k]] == lowered_sources_[k]) region_[lowered_sources_[k]].push_back(lowered_[k]);
      }
      return false;
    }
    mine.clear();
    for (const VertexId c : t) {
      if (owner_[c] == i) mine.push_back(c);
    }
    for (std::size_t k = 0; k < lowered_.size(); ++k) region_[lowered_sources_[k]].push_back(lowered_[k]);
    return true;
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
  DeviceSurfaceVoronoi* device_;  // the diagrams on the device, when given
  EveningDiagrams diagrams_;
  const SurfaceWalk walk_;
  const EveningLimits limits_;
  const unsigned threads_;
  std::vector<SurfaceLocation> points_;
  CornerIndex corners_;
  std::vector<char> visit_;
  std::vector<SurfaceGap> gaps_;     // one per thread
  std::vector<Proposal> proposals_;  // of the set in hand, in its order
  // The sets' stamps: per particle, the set it moved in; per vertex, the
  // set in which a particle moved from or to a triangle of it.
  std::uint32_t set_stamp_ = 0;
  std::vector<std::uint32_t> moved_in_set_, stamp_;
  SolverScratch scratch_;
  SurfaceVoronoi cells_;
  NeighbourLists lists_;  // of cells_
  // The diagram as this sweep's moves have left it: each vertex's distance
  // to its nearest particle (measured, an upper bound) and which that is.
  std::vector<float> nearest_;
  std::vector<std::uint32_t> owner_;
  std::vector<std::vector<VertexId>> region_;  // per particle: every vertex it owns (and some it no longer does)
  struct Undo {
    VertexId vertex;
    float nearest;
    std::uint32_t owner;
  };
  std::vector<Undo> undo_;
  std::vector<VertexId> rim_, lowered_;
  std::vector<std::uint32_t> rim_sources_, lowered_sources_;
  std::vector<std::uint32_t> lowered_owners_;  // the owners before the march, parallel to lowered_
  std::vector<float> lowered_was_;             // the distances before it
};

}  // namespace

EveningOutcome even_out(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> points,
                        const EveningLimits& limits, unsigned threads, bool quiet, DeviceSurfaceVoronoi* device) {
  threads = cores_or(threads);
  // Each thread marches with scratch arrays over the whole mesh: no more
  // threads than a quarter of the usable memory holds (--threads 1024 on
  // a working mesh of 4M vertices would ask 70 GB).
  const std::uint64_t scratch_bytes = kScratchBytesPerVertex * std::max<std::uint64_t>(mesh.vertex_count(), 1);
  threads = unsigned(std::clamp<std::uint64_t>(usable_host_memory_bytes() / 4 / scratch_bytes, 1, threads));
  Evening evening(mesh, solver, std::move(points), limits, threads, device);
  std::vector<EveningSweep> sweeps;
  ProgressLine progress("even", limits.max_sweeps, quiet);
  for (std::size_t sweep = 1; sweep <= limits.max_sweeps; ++sweep) {
    sweeps.push_back(evening.sweep());
    const EveningSweep& record = sweeps.back();
    progress.update(sweep, "smallest spacing " + format_number("%.4f", record.smallest / limits.d_hex) + " d_hex, " +
                               std::to_string(record.moved) + " moved");
    // Stalled: kStallSweeps sweeps in a row each raised the mean spacing by
    // under limits.stall_gain.
    bool stalled = sweeps.size() > kStallSweeps;
    for (std::size_t k = 1; stalled && k <= kStallSweeps; ++k) {
      stalled = sweeps[sweeps.size() - k].mean - sweeps[sweeps.size() - k - 1].mean < limits.stall_gain;
    }
    if (record.moved == 0 || stalled) break;
  }
  progress.finish();
  return evening.outcome(std::move(sweeps));
}

}  // namespace meshparticles
