#include "particles/local_farthest_points.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "common/elapsed.hpp"
#include "common/parallel_for.hpp"
#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "geodesics/memory_guard.hpp"
#include "geodesics/point_seeds.hpp"
#include "particles/cavity_centre.hpp"
#include "particles/spread_working_mesh.hpp"
#include "particles/surface_voronoi.hpp"

namespace meshparticles {

namespace {

// Neighbours this many steps apart in the diagram's graph are listed too:
// where the surface folds or a part is thin, a particle two or three steps
// away can be nearer a cavity's centre than its neighbours are.
constexpr int kReachSteps = 3;
// Sweeps stop once this many in a row have each raised the mean spacing by
// under the stall gain: a sweep of few moves can open room for the next
// (measured on dino and cow at n = 1,024: 5 in a row gave the same rho as
// 2, in 13 sweeps against 9 or 10).
constexpr std::size_t kStallSweeps = 2;
// A move's length along the surface is taken as at most this many times
// its straight length where the cover is bounded without a march.
constexpr double kMoveSlack = 1.1;
// What a thread's scratch holds per vertex (SolverScratch::fit: accepted,
// heap_slot, origin, distances; CavityScratch's rows).
constexpr std::uint64_t kScratchBytesPerVertex = 1 + 4 + 4 + 8 + 4;
// Each particle's ball reaches this many spacings: past the widest gap of
// any cavity (about one spacing) to the far corners of the triangles there,
// so that a triangle where a ball stops has some nearer particle's ball at
// all three corners. The marches are a third of the evening; at 1.25
// against 1.5 the 46 corpus runs, on working meshes whose edges are at
// most kSpreadLongestEdge (0.3 spacings), give the same medians (rho 0.899,
// nn_cv 0.018), the sweeps a fifth faster. On a coarser mesh the ball
// reaches as much further as its longest edge is longer than that (the
// torus at 256, edges to 0.78 d_hex: at 1.25 alone the evening ends at
// nn_min 0.77 against 0.91).
constexpr double kBallReach = 1.25;
// A region past the cover limit is drawn in by moving its particle toward
// its farthest vertex, by the least of these multiples of the overshoot's
// share of that distance that covers the region within the limit (a step
// of exactly the share would leave the far vertex at the limit only on a
// flat, straight way there).
constexpr std::array<double, 4> kHoleStepMultiples = {1.25, 2.0, 3.0, 4.0};
// and never by more than this share of the way.
constexpr double kLongestHoleStep = 0.9;

// Per particle, the particles within kReachSteps steps of the diagram's
// graph: the neighbours (regions touching) and the rest.
struct NeighbourLists {
  std::vector<std::vector<std::uint32_t>> near;    // regions touching
  std::vector<std::vector<std::uint32_t>> around;  // 2 to kReachSteps steps away, in the order reached
};

NeighbourLists neighbour_lists(const SurfaceMesh& mesh, const SurfaceVoronoi& cells, std::size_t particles,
                               unsigned threads) {
  NeighbourLists lists;
  lists.near.resize(particles);
  lists.around.resize(particles);
  for (const SurfacePath& path : cells.neighbour_paths(mesh)) {
    lists.near[path.a].push_back(path.b);
    lists.near[path.b].push_back(path.a);
  }
  // Each particle's steps outward through the graph: one thread's marks per slot.
  std::vector<std::vector<char>> seens(threads);
  std::vector<std::vector<std::uint32_t>> frontiers(threads), nexts(threads);
  for_each_with_slot(particles, threads, [&](std::size_t particle, unsigned slot) {
    const auto i = std::uint32_t(particle);
    std::vector<char>& seen = seens[slot];
    std::vector<std::uint32_t>& frontier = frontiers[slot];
    std::vector<std::uint32_t>& next = nexts[slot];
    if (seen.empty()) seen.assign(particles, 0);
    seen[i] = 1;
    for (const std::uint32_t k : lists.near[i]) seen[k] = 1;
    frontier = lists.near[i];
    for (int step = 1; step < kReachSteps; ++step) {
      next.clear();
      for (const std::uint32_t k : frontier) {
        for (const std::uint32_t l : lists.near[k]) {
          if (seen[l]) continue;
          seen[l] = 1;
          lists.around[i].push_back(l);
          next.push_back(l);
        }
      }
      frontier.swap(next);
    }
    seen[i] = 0;
    for (const std::uint32_t k : lists.near[i]) seen[k] = 0;
    for (const std::uint32_t k : lists.around[i]) seen[k] = 0;
  });
  return lists;
}

// What a particle's move is judged against, read only while proposals are
// computed: the state as the moves before them left it.
struct EveningView {
  const CavitySurface& surface;
  const EveningLimits& limits;
  const NeighbourLists& lists;
  const std::vector<SurfaceLocation>& points;
  const std::vector<vec3d>& positions;  // the points', as the cavity centre reads them
  const ParticleBalls& balls;           // per particle, where it stands
  const std::vector<std::uint32_t>& owner;     // per vertex: the diagram's nearest particle
  const std::vector<std::vector<VertexId>>& region;  // per particle: its vertices (and some it no longer owns)
};

// One particle's move as proposed: where to, and what it read.
struct Proposal {
  bool move = false;      // the centre of its cavity widens its gap
  SurfaceLocation there;  // where to, when it does
  // The vertices of its region (a commit that gives one another owner
  // changes the proposal).
  std::vector<VertexId> read;
};

// Particle i's move, a function of i and the state `view` alone: to the
// centre of its cavity (cavity_centre: the point of its region farthest
// along the surface from the particles listed for it), where that is
// farther from them than where i stands by more than the minimum gain.
// The cover is judged at the commit (Evening::covered_after_move). One
// work-item per particle on a device (DeviceCavityCentres), the same
// steps: the region read (read_region), the centre, the decision (decide_move).
void read_region(std::uint32_t i, const EveningView& view, Proposal& proposal) {
  proposal.read.clear();
  for (const VertexId v : view.region[i]) {
    if (view.owner[v] == i) proposal.read.push_back(v);
  }
}

Cavity cavity_in(std::uint32_t i, const EveningView& view, const Proposal& proposal) {
  return {view.points[i], proposal.read, view.lists.near[i], view.lists.around[i]};
}

void decide_move(const CavityCentre& centre, const EveningLimits& limits, Proposal& proposal) {
  proposal.move = std::isfinite(centre.here) && centre.away > centre.here + limits.min_gain;
  if (proposal.move) proposal.there = centre.at;
}

void propose_move(std::uint32_t i, const EveningView& view, CavityScratch& scratch, Proposal& proposal) {
  read_region(i, view, proposal);
  decide_move(cavity_centre(view.surface, cavity_in(i, view, proposal), view.positions, view.balls, scratch),
              view.limits, proposal);
}

// The particles to visit in sets whose moves cannot meet: a greedy
// colouring by index of the graph joining each particle to those within
// kReachSteps steps (its lists, whose balls are all a proposal reads of others).
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
      for (const std::uint32_t k : *list) {
        if (colour[k] != kNone) taken[colour[k]] = 1;
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
          const EveningLimits& limits, unsigned threads, EveningDevice device)
      : mesh_(mesh), solver_(solver), device_(device), walk_(mesh), surface_(mesh, walk_.triangles_around()),
        limits_(limits), threads_(std::max(1u, threads)), points_(std::move(points)), visit_(points_.size(), 1),
        scratches_(threads_), ball_scratches_(threads_), seeds_(threads_), balls_(points_.size()),
        ball_reach_(kBallReach * limits.d_hex + std::max(0.0, longest_edge(mesh) - kSpreadLongestEdge * limits.d_hex)),
        moved_in_set_(points_.size(), 0), stamp_(mesh.vertex_count(), 0) {
    find_neighbours();
    for (const SurfaceLocation& p : points_) {
      positions_.push_back(to_vec3d(p.at));
      triangles_.push_back(p.triangle);
    }
    movers_.resize(points_.size());
    for (std::uint32_t k = 0; k < points_.size(); ++k) movers_[k] = k;
    march_balls();
    double mean = 0;
    measure_spacings(mean, kept_.smallest);
    kept_.points = points_;
    kept_.cover = cells_.cover();
    start_cover_ = kept_.cover;
  }

  // One sweep over the particles to visit; its record. The particles go in
  // independent sets (independent_sets): each set's moves are proposed at
  // once against the state the sets before it left (propose_move, on
  // threads_ threads), then committed in index order, each after its cover
  // check, and the balls of those that moved marched again (on threads_
  // threads). A proposal that read what a commit of its own set changed (a
  // particle of its lists moved, or a vertex of its region went to another
  // particle: a colouring by graph steps does not bound the diagram's
  // marches) is computed again at its commit. So the result is that of
  // visiting the particles one by one in the sets' order, whatever the
  // number of threads.
  EveningSweep sweep() {
    const auto started = std::chrono::steady_clock::now();
    EveningSweep record;
    record.cover = cells_.cover();
    std::vector<char> moved(points_.size(), 0);
    if (limits_.hold_cover && cells_.cover() > limits_.cover) draw_into_holes(moved, record);
    for (const std::vector<std::uint32_t>& set : independent_sets(lists_, visit_)) {
      ++set_stamp_;
      if (proposals_.size() < set.size()) proposals_.resize(set.size());
      const EveningView view{surface_, limits_, lists_, points_, positions_, balls_, owner_, region_};
      const auto proposing = std::chrono::steady_clock::now();
      if (!device_.moves || !propose_on_device(set, view)) {
        for_each_with_slot(set.size(), threads_, [&](std::size_t k, unsigned slot) {
          propose_move(set[k], view, scratches_[slot], proposals_[k]);
        });
      }
      proposing_seconds_ += seconds_since(proposing);
      for (std::size_t k = 0; k < set.size(); ++k) {
        const std::uint32_t i = set[k];
        Proposal& proposal = proposals_[k];
        if (read_a_commit(i, proposal)) {
          propose_move(i, view, scratches_[0], proposal);
        }
        const Vec3 was = points_[i].at;
        if (proposal.move && commit(i, proposal.there)) {
          moved[i] = 1;
          record.longest = std::max(record.longest, distance(was, points_[i].at));
        }
      }
      movers_.clear();
      for (const std::uint32_t i : set) {
        if (moved_in_set_[i] == set_stamp_) movers_.push_back(i);
      }
      march_balls();
    }
    record.moved = std::size_t(std::count(moved.begin(), moved.end(), 1));
    find_neighbours(&moved);
    summarize(moved, record);
    record.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return record;
  }

  // The smallest spacing of the points kept (mesh units).
  double kept_smallest() const { return kept_.smallest; }
  // The `count` particles whose gaps are smallest where the particles stand
  // now (ties: the lower index): the ends of the closest pair first.
  std::vector<std::uint32_t> closest_particles(std::size_t count) const {
    std::vector<std::uint32_t> order(points_.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    count = std::min(count, order.size());
    const auto narrower = [&](std::uint32_t a, std::uint32_t b) {
      return gaps_[a] < gaps_[b] || (gaps_[a] == gaps_[b] && a < b);
    };
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(count), order.end(), narrower);
    order.resize(count);
    return order;
  }
  // The vertex farthest from every particle in the diagram of where they
  // stand now (ties: the lower index; a vertex of a component no particle
  // reaches is none), as a point of the surface.
  SurfaceLocation widest_hole() const {
    VertexId widest = 0;
    float farthest = -1;
    for (VertexId v = 0; v < cells_.distance.size(); ++v) {
      if (std::isfinite(cells_.distance[v]) && cells_.distance[v] > farthest) {
        widest = v;
        farthest = cells_.distance[v];
      }
    }
    return walk_.at_vertex(widest);
  }

  EveningOutcome outcome(std::vector<EveningSweep> sweeps) {
    if (device_.diagrams) {
      diagrams_.device = device_.diagrams->device_name();
      diagrams_.rounds = device_.diagrams->statistics().rounds;
    }
    EveningMoves moves;
    moves.seconds = proposing_seconds_;
    if (device_.moves) {
      const DeviceCavityCentres::Statistics& on = device_.moves->statistics();
      moves.device = device_.moves->device_name();
      moves.launches = on.launches;
      moves.sets_on_host = on.sets_on_host;
      moves.device_seconds = on.seconds;
    }
    return {std::move(kept_.points), std::move(sweeps), kept_.cover, diagrams_, moves, kept_.sweep, {}};
  }

 private:
  // Holding the cover: a region can be over the limit where the evening
  // started so (as a swap leaves the place its particle left), or where
  // the diagram's update reads a region a little wider than the move's
  // check did (lion at 1,024: 0.821 d_hex against a limit of 0.799). The
  // sweeps' moves, each widening its own gap, close such a hole only where
  // one of them stands with it ahead. A particle may stand at its cavity's
  // centre with its region's far side at its back, one neighbour a spacing
  // and more away in front (femur at 256: a swapped particle 1.06 d_hex
  // from its one neighbour, the far side of its region 0.84 d_hex behind,
  // over the limit of 0.79, in every sweep).
  // So each particle whose region reaches past the limit is first moved
  // toward its farthest vertex, by the least step that brings its region
  // within the limit (kHoleStepMultiples), where its gap stays at least
  // the smaller of its own and the wider of the smallest spacing and the
  // swaps' target: the move never makes the closest pair. In index order,
  // on the diagram the sweep starts from; `record` counts them.
  void draw_into_holes(std::vector<char>& moved, EveningSweep& record) {
    ++set_stamp_;
    std::vector<VertexId> farthest(points_.size(), 0);
    std::vector<float> reach(points_.size(), 0);
    for (VertexId v = 0; v < owner_.size(); ++v) {
      const std::uint32_t i = owner_[v];
      if (i != SurfaceVoronoi::kNoPoint && nearest_[v] > limits_.cover && nearest_[v] > reach[i]) {
        reach[i] = nearest_[v];
        farthest[i] = v;
      }
    }
    double smallest = std::numeric_limits<double>::infinity();
    for (const double gap : gaps_) smallest = std::min(smallest, gap);
    movers_.clear();
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (reach[i] == 0) continue;
      const double overshoot = (reach[i] - limits_.cover) / reach[i];
      const double least_gap = std::min(gaps_[i], std::max(smallest, limits_.swap_below));
      const Vec3 from = points_[i].at, to = mesh_.positions()[farthest[i]];
      for (const double multiple : kHoleStepMultiples) {
        const double share = std::min(kLongestHoleStep, multiple * overshoot);
        const SurfaceLocation there = walk_.walk(points_[i].triangle, from + share * (to - from));
        if (!(gap_at(i, there) >= least_gap)) break;  // too near another: no longer step is tried
        if (commit(i, there, true)) {
          moved[i] = 1;
          movers_.push_back(i);
          record.longest = std::max(record.longest, distance(from, there.at));
          break;
        }
      }
    }
    march_balls();
    record.drawn = movers_.size();
  }

  // The proposals of `set` with their cavities' centres on the device
  // (the regions read on threads_ threads, the decisions on the host);
  // false where the device left them to the host.
  bool propose_on_device(const std::vector<std::uint32_t>& set, const EveningView& view) {
    for_each_with_slot(set.size(), threads_, [&](std::size_t k, unsigned) { read_region(set[k], view, proposals_[k]); });
    std::vector<Cavity> cavities;
    cavities.reserve(set.size());
    for (std::size_t k = 0; k < set.size(); ++k) cavities.push_back(cavity_in(set[k], view, proposals_[k]));
    const std::optional<std::vector<CavityCentre>> centres =
        device_.moves->centres(set, cavities, positions_, triangles_, balls_);
    if (!centres) return false;
    for (std::size_t k = 0; k < set.size(); ++k) decide_move((*centres)[k], limits_, proposals_[k]);
    return true;
  }

  // The balls of movers_: the vertices within kBallReach spacings of where
  // each stands, marched from its corners' fans (geodesics/point_seeds), on
  // threads_ threads, then put in balls_ in movers_' order.
  void march_balls() {
    if (marched_.size() < movers_.size()) marched_.resize(movers_.size());
    for_each_with_slot(movers_.size(), threads_, [&](std::size_t m, unsigned slot) {
      point_seeds(mesh_, walk_.triangles_around(), points_[movers_[m]], seeds_[slot]);
      solver_.solve_ball_from(seeds_[slot].vertices, seeds_[slot].distances, ball_reach_, ball_scratches_[slot],
                              marched_[m]);
      std::sort(marched_[m].begin(), marched_[m].end());  // by vertex, as balls_ keeps them
    });
    for (std::size_t m = 0; m < movers_.size(); ++m) balls_.set(movers_[m], marched_[m]);
  }

  // Particle i's distance from the nearest particle listed for it, each
  // read through its ball at i's triangle's corners (a source in the
  // triangle's plane, as cavity_centre reads them).
  double gap_from_balls(std::uint32_t i) const { return gap_at(i, points_[i]); }
  // The same, were i at `p`.
  double gap_at(std::uint32_t i, const SurfaceLocation& p) const {
    const plane_frame frame = triangle_frame(mesh_, p.triangle);
    if (frame_degenerate(frame)) return std::numeric_limits<double>::infinity();
    const Triangle& t = mesh_.triangles()[p.triangle];
    const vec3d at = to_vec3d(p.at);
    const double x = frame_x(frame, at), y = frame_y(frame, at);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto* list : {&lists_.near[i], &lists_.around[i]}) {
      for (const std::uint32_t k : *list) {
        const std::span<const ball_entry> ball = balls_[k];
        std::array<double, 3> d{};
        bool reached = true;
        for (int c = 0; c < 3 && reached; ++c) {
          const auto found = std::lower_bound(ball.begin(), ball.end(), t[c],
                                              [](const ball_entry& entry, VertexId v) { return entry.vertex < v; });
          reached = found != ball.end() && found->vertex == t[c];
          if (reached) d[c] = found->distance;
        }
        if (reached) {
          nearest = std::min(nearest, planar_source_distance(frame, planar_source_of(frame, d[0], d[1], d[2]), x, y));
        }
      }
    }
    return nearest;
  }

  // Whether i's proposal read what a commit of its own set has changed since.
  bool read_a_commit(std::uint32_t i, const Proposal& proposal) const {
    for (const auto* list : {&lists_.near[i], &lists_.around[i]}) {
      for (const std::uint32_t k : *list) {
        if (moved_in_set_[k] == set_stamp_) return true;
      }
    }
    return std::any_of(proposal.read.begin(), proposal.read.end(),
                       [&](VertexId v) { return stamp_[v] == set_stamp_; });
  }

  // Moves i to `there` where that holds the cover; whether it moved.
  bool commit(std::uint32_t i, const SurfaceLocation& there, bool strict = false) {
    if (!covered_after_move(i, there, strict)) return false;
    moved_in_set_[i] = set_stamp_;
    points_[i] = there;
    positions_[i] = to_vec3d(there.at);
    triangles_[i] = there.triangle;
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
    if (moved && device_.diagrams) {
      device_.diagrams->update(points_, *moved, cells_);
    } else if (moved) {
      update_surface_voronoi(mesh_, solver_, points_, *moved, cells_, scratch_);
    } else if (device_.diagrams) {
      cells_ = device_.diagrams->diagram(points_);
    } else {
      cells_ = surface_voronoi(mesh_, solver_, points_, scratch_);
    }
    diagrams_.seconds += seconds_since(started);
    ++diagrams_.count;
    lists_ = neighbour_lists(mesh_, cells_, points_.size(), threads_);
    nearest_ = cells_.distance;
    owner_ = cells_.owner;
    region_.assign(points_.size(), {});
    for (VertexId v = 0; v < owner_.size(); ++v) {
      if (owner_[v] != SurfaceVoronoi::kNoPoint) region_[owner_[v]].push_back(v);
    }
  }

  // Whether moving i to `there` leaves every vertex of i's region within
  // limits_.cover of a particle (where the evening started over it, no
  // farther than the region's farthest was; with `strict`, within
  // limits_.cover whatever the start), on the diagram as the sweep's
  // moves have left it (nearest_, owner_): the region i holds is refilled
  // from its rim by the particles around it (one march from the rim, each
  // rim vertex from its own particle, as particle_voronoi refills a
  // region), and a march from `there` takes what is nearer to it. Where the
  // move holds the cover the diagram is left updated for it, else as it
  // was.
  bool covered_after_move(std::uint32_t i, const SurfaceLocation& there, bool strict = false) {
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
    // Where the evening started over the limit (a swap's hole), a region
    // over it may narrow but not widen: else no particle around the hole
    // could move toward it without covering all of it at once. Never past
    // the start's cover: the diagram's update can read a region a little
    // wider than this check did, and a region over the limit that way is
    // held, not let grow (lion at 1,024: 0.821 d_hex, 0.844 with any
    // region free to stay as wide as it was).
    const double limit =
        strict ? limits_.cover : std::max(limits_.cover, std::min(double(reach), start_cover_));
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
    for (const VertexId v : mine) stamp_[v] = set_stamp_;
    for (const VertexId v : lowered_) stamp_[v] = set_stamp_;
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
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      visit_[i] = moved[i];
      for (const std::uint32_t k : lists_.near[i]) visit_[i] = visit_[i] || moved[k];
    }
    measure_spacings(record.mean, record.smallest);
    ++sweeps_done_;
    // Holding the cover, a sweep within the limit comes before any that is
    // not (a swap is kept only so).
    const double cover = cells_.cover();
    const bool within = cover <= limits_.cover, kept_within = kept_.cover <= limits_.cover;
    const bool keep =
        (limits_.hold_cover && within != kept_within) ? within : record.smallest >= kept_.smallest;
    if (keep) kept_ = {points_, cover, record.smallest, sweeps_done_};
  }

  // The mean and smallest of each particle's spacing to its nearest: the
  // least of the listed particles' balls read where it stands.
  void measure_spacings(double& mean, double& smallest_gap) {
    gaps_.resize(points_.size());
    for_each_with_slot(points_.size(), threads_, [&](std::size_t i, unsigned) { gaps_[i] = gap_from_balls(std::uint32_t(i)); });
    double sum = 0, smallest = std::numeric_limits<double>::infinity();
    std::size_t counted = 0;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      const double gap = gaps_[i];
      if (!std::isfinite(gap)) continue;
      sum += gap;
      smallest = std::min(smallest, gap);
      ++counted;
    }
    mean = counted ? sum / double(counted) : 0;
    smallest_gap = counted ? smallest : 0;
  }

  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  const EveningDevice device_;  // the diagrams and the moves on the device, where given
  EveningDiagrams diagrams_;
  const SurfaceWalk walk_;
  const CavitySurface surface_;  // the mesh as cavity_centre reads it
  const EveningLimits limits_;
  const unsigned threads_;
  std::vector<SurfaceLocation> points_;
  std::vector<vec3d> positions_;  // points_' points
  std::vector<std::uint32_t> triangles_;  // and their triangles
  std::vector<char> visit_;
  std::vector<CavityScratch> scratches_;     // one per thread
  std::vector<SolverScratch> ball_scratches_;  // one per thread
  std::vector<PointSeeds> seeds_;              // one per thread
  ParticleBalls balls_;                        // per particle, where it stands
  std::vector<ParticleBall> marched_;          // movers_' balls as marched, before they go into balls_
  const double ball_reach_;                    // how far each ball is marched (mesh units)
  std::vector<std::uint32_t> movers_;          // of the set in hand (at the start: every particle)
  std::vector<Proposal> proposals_;            // of the set in hand, in its order
  // The particles kept: those of the sweep whose smallest spacing is
  // widest, the last of equals (0: the start). A move never narrows its own particle's gap
  // as the balls read it, but a ball from one end of a pair reads it a few
  // hundredths of a spacing otherwise than one from the other end, so a
  // later sweep can end with a narrower pair than an earlier one (the
  // sphere at 256: 0.913 after sweep 13, 0.884 after 14, 0.923 after 27).
  struct Kept {
    std::vector<SurfaceLocation> points;
    double cover = 0, smallest = 0;
    std::size_t sweep = 0;
  } kept_;
  std::size_t sweeps_done_ = 0;
  double proposing_seconds_ = 0;  // the sets' proposals, wherever found
  double start_cover_ = 0;  // the diagram's cover where the evening started
  std::vector<double> gaps_;  // per particle, measure_spacings's
  // The sets' stamps: per particle, the set it moved in; per vertex, the
  // set in which a commit gave it another owner.
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

// Sweeps `evening` until one moves nothing, kStallSweeps in a row each
// raise the mean spacing by under limits.stall_gain, or limits.max_sweeps
// have run; reported on `progress` where given.
std::vector<EveningSweep> sweep_until_still(Evening& evening, const EveningLimits& limits, ProgressLine* progress) {
  std::vector<EveningSweep> sweeps;
  for (std::size_t sweep = 1; sweep <= limits.max_sweeps; ++sweep) {
    sweeps.push_back(evening.sweep());
    const EveningSweep& record = sweeps.back();
    if (progress) {
      progress->update(sweep, "smallest spacing " + format_number("%.4f", record.smallest / limits.d_hex) +
                                  " d_hex, " + std::to_string(record.moved) + " moved");
    }
    bool stalled = sweeps.size() > kStallSweeps;
    for (std::size_t k = 1; stalled && k <= kStallSweeps; ++k) {
      stalled = sweeps[sweeps.size() - k].mean - sweeps[sweeps.size() - k - 1].mean < limits.stall_gain;
    }
    if (record.moved == 0 || stalled) break;
  }
  return sweeps;
}

// The swaps after the sweeps (even_out): `outcome`, whose smallest spacing
// is `smallest`, is replaced by each swap kept.
void swap_closest_into_widest(const SurfaceMesh& mesh, const GeodesicSolver& solver, const EveningLimits& limits,
                              unsigned threads, bool quiet, EveningDevice device, EveningOutcome& outcome,
                              double smallest) {
  if (limits.swap_rounds == 0 || !(smallest < limits.swap_below)) return;
  ProgressLine progress("swap", limits.swap_rounds, quiet);
  for (std::size_t round = 1; round <= limits.swap_rounds && smallest < limits.swap_below; ++round) {
    const Evening at(mesh, solver, outcome.points, limits, threads, device);
    const SurfaceLocation hole = at.widest_hole();
    std::optional<EveningOutcome> widest;
    std::size_t widest_swap = 0;
    for (const std::uint32_t particle : at.closest_particles(2)) {
      const auto started = std::chrono::steady_clock::now();
      std::vector<SurfaceLocation> swapped = outcome.points;
      swapped[particle] = hole;
      Evening again(mesh, solver, std::move(swapped), limits, threads, device);
      std::vector<EveningSweep> sweeps = sweep_until_still(again, limits, nullptr);
      EveningSwap swap{particle, again.kept_smallest(), 0, sweeps.size(), 0, false};
      EveningOutcome tried = again.outcome(std::move(sweeps));
      swap.cover = tried.cover;
      swap.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
      outcome.diagrams.count += tried.diagrams.count;
      outcome.diagrams.seconds += tried.diagrams.seconds;
      outcome.diagrams.rounds = tried.diagrams.rounds;  // the device's counts run on
      outcome.moves.seconds += tried.moves.seconds;
      outcome.moves.launches = tried.moves.launches;  // as the rounds
      outcome.moves.sets_on_host = tried.moves.sets_on_host;
      outcome.moves.device_seconds = tried.moves.device_seconds;
      if (swap.smallest > smallest && tried.cover <= limits.cover &&
          (!widest || swap.smallest > outcome.swaps[widest_swap].smallest)) {
        widest = std::move(tried);
        widest_swap = outcome.swaps.size();
      }
      outcome.swaps.push_back(swap);
    }
    const std::string result =
        widest ? " -> " + format_number("%.4f", outcome.swaps[widest_swap].smallest / limits.d_hex)
               : std::string(", no swap widens it");
    progress.update(round, "smallest spacing " + format_number("%.4f", smallest / limits.d_hex) + " d_hex" + result);
    if (!widest) break;
    outcome.swaps[widest_swap].kept = true;
    outcome.points = std::move(widest->points);
    outcome.cover = widest->cover;
    smallest = outcome.swaps[widest_swap].smallest;
  }
  progress.finish();
}

}  // namespace

EveningOutcome even_out(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::vector<SurfaceLocation> points,
                        const EveningLimits& limits, unsigned threads, bool quiet, EveningDevice device) {
  threads = cores_or(threads);
  // Each thread marches with scratch arrays over the whole mesh: no more
  // threads than a quarter of the usable memory holds (--threads 1024 on
  // a working mesh of 4M vertices would ask 70 GB).
  const std::uint64_t scratch_bytes = kScratchBytesPerVertex * std::max<std::uint64_t>(mesh.vertex_count(), 1);
  threads = unsigned(std::clamp<std::uint64_t>(usable_host_memory_bytes() / 4 / scratch_bytes, 1, threads));
  Evening evening(mesh, solver, std::move(points), limits, threads, device);
  ProgressLine progress("even", limits.max_sweeps, quiet);
  std::vector<EveningSweep> sweeps = sweep_until_still(evening, limits, &progress);
  progress.finish();
  const double smallest = evening.kept_smallest();
  EveningOutcome outcome = evening.outcome(std::move(sweeps));
  swap_closest_into_widest(mesh, solver, limits, threads, quiet, device, outcome, smallest);
  return outcome;
}

}  // namespace meshparticles
