#include "correspondence/joint_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

#include "common/median.hpp"
#include "common/parallel_for.hpp"
#include "common/progress.hpp"
#include "correspondence/correspondence_term.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "particles/hole_pull.hpp"
#include "particles/hole_swap.hpp"
#include "particles/local_farthest_points.hpp"
#include "particles/packing_relaxation.hpp"
#include "particles/particle_params.hpp"
#include "particles/surface_neighbours.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/widest_hole.hpp"
#include "shape_model/corresponding_points.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles {

namespace {

// A step is at most this share of the shape's spacing: no particle jumps
// over a neighbour, and the walk stays short.
constexpr double kLargestStep = 0.3;
// Each particle of a pair closer than the spacing moves away by this share of
// the overlap: a quarter, not a half, because a crowded particle is pushed by
// several neighbours at once, and half each overshoots into a jostle (nn_cv
// 0.040 against 0.022 at n = 256 on the ellipsoid population).
constexpr double kPush = 0.25;
// Over the packing's first rounds the correspondence step's weight fades
// from the iterations' to the share the packing holds
// (JointRefinementOptions::packing_hold); the rounds stop when no shape's
// smallest spacing grows any more, or after kPackingRounds (and as many
// again for the shapes released).
constexpr std::size_t kFadingRounds = 50;
constexpr std::size_t kPackingRounds = 1000;
// The smallest step of the packing's growing radius, a share a round: the
// 0.2% it was measured with (spread's relaxation grows by 0.3% since stop
// 82; not measured on populations).
constexpr double kSmallestGrowth = 0.002;
// Each round (and each iteration), every point of a shape's surface farther
// than kHoleReach of its spacing from its particle draws that particle
// toward it (particles/hole_pull), kHoleGain of the pull joining the step:
// the pushes only part pairs too close, so without it nothing closes a
// hole that the correspondence step holds open (on a bump that grows, up
// to 1.5 spacings wide at n = 1,024). A hexagonal packing leaves no point
// farther than 0.577, so a reach a little under it also evens out what is
// nearly hexagonal. Measured on the radii and ellipsoid populations at
// n = 512 and 1,024, the worst shape's cover over its own run's: 1.23x to
// 1.34x without it; at reach 0.7 or gain 0.2 still over 1.15x; at reach
// 0.6, 1.09x (gain 0.5) and 1.07x (gain 1); at 0.55 and gain 1, 1.05x,
// and particle i's spread fell most (0.307 to 0.238 at the median on the
// ellipsoids at 1,024).
constexpr double kHoleReach = 0.55;
constexpr double kHoleGain = 1.0;
// The surface's points about a quarter spacing apart.
constexpr double kHoleSampleStep = 0.25;
// A shape whose held packing still leaves a hole this wide (in its
// hexagonal spacings, at those points) is released to pack on its own.
// Own runs cover about 0.75.
constexpr double kHeldOpenCover = 0.9;
// A shape held back from its evening may leave holes at most this much
// wider than the evened shape's (straight covers at points of its surface
// kHeldCoverSampleStep of its spacing apart: at the vertices alone, with
// 2 to 4 of them a particle, the holes between them went unseen).
constexpr double kHeldCover = 1.05;
constexpr double kHeldCoverSampleStep = 0.15;
// ... and lie at most this much farther (squared) from the other shapes'
// mean (aligned as the model aligns them) than the evened shape does.
constexpr double kHeldOffTheOthers = 2;
// A shape still closer than even enough then takes at most this many sweeps
// of spread's evening (particles/local_farthest_points), each move widening
// its particle's gap by over kGapMinGain of a spacing, until a sweep widens
// the mean gap by under kGapStallGain. FAUST's people at n = 256 stall after 4.
constexpr std::size_t kGapSweeps = 8;
constexpr double kGapMinGain = 0.01;
constexpr double kGapStallGain = 0.001;
// Then particles taken from a crowd into a hole (particles/hole_swap):
// one a kParticlesPerSwap of them at most (at least kLeastSwaps), while the
// shape's closest pair is under even enough or its widest hole over
// kSwapHole times the template's own run's (the target is 1.15x
// the shape's own run's). A crowd left by the transfer grows with n: at
// n = 1,024 one of FAUST's poses took 98 to part its pairs (rho least 0.54 to 0.70).
constexpr std::size_t kParticlesPerSwap = 8;
constexpr std::size_t kLeastSwaps = 8;
// A crowd is carried into a hole far off only where its pair is closer than
// this (in the shape's hexagonal spacings; the rho target) and no
// local swap helps: carried at every chance, FAUST's people at n = 256
// spread 0.31 / 0.52, not 0.28 / 0.41.
constexpr double kCarryBelow = 0.7;
// ... or where the shape's widest hole is over this many times the
// template's own run's (the target ratio, 1.15x): FAUST's poses at
// n = 256 after 0.15.0's evening, tr_reg_007 held a hole of 0.95 spacings
// (1.28x the template's) after 3 swaps, its closest pair 0.79 apart, and
// no local move narrowed it (cover 1.20x its own run's; carried, 1.06x).
constexpr double kCarryAbove = 1.15;
constexpr std::size_t kSwapSteps = 2;
constexpr double kSwapHole = 1.05;

PointSet positions(const std::vector<SurfaceLocation>& at) {
  PointSet points(Eigen::Index(at.size()), 3);
  for (std::size_t i = 0; i < at.size(); ++i) points.row(Eigen::Index(i)) << at[i].at.x, at[i].at.y, at[i].at.z;
  return points;
}

// One owned shape's surface, for the questions asked of its particles
// along it: a solver, which pairs are neighbours, where its holes are.
// `hole_step`: its points that find holes this far apart. Every shape holds
// one through the whole refinement, so the working memory of its marches
// is not here but the thread's (a LookScratch, lent by for_each_owned):
// held per shape it was about 0.45 MB of 10,000 vertices (10 such shapes
// at n = 1,024: 62.6 MB of heap through the iterations, 57.7 MB lent).
struct ShapeSurface {
  ShapeSurface(const SurfaceMesh& mesh, double hole_step)
      : solver(make_geodesic_solver(mesh, GeodesicMethod::fast_marching)),
        neighbours(mesh, *solver),
        pairs(mesh, *solver),
        holes(mesh, *solver, hole_step) {}
  std::unique_ptr<GeodesicSolver> solver;
  SurfaceNeighbours neighbours;
  SurfacePairs pairs;  // the same question, step after step
  HolePull holes;
};

// A LookScratch for each thread of `share`.
std::vector<LookScratch> threads_scratch(const ShapeShare& share) {
  return std::vector<LookScratch>(std::max(1u, share.threads()));
}

// work(k, scratch) for every owned shape k on the share's threads, each
// with the scratch of the thread running it (`scratch`: threads_scratch's).
// The same bytes for any number of threads: a march leaves the solver's
// part clean, and a look's answers are read only by the shape that made
// them, before its thread takes another.
void for_each_owned(ShapeShare& share, std::vector<LookScratch>& scratch,
                    const std::function<void(std::size_t, LookScratch&)>& work) {
  const std::vector<std::size_t> owned = share.owned();
  for_each_with_slot(owned.size(), share.threads(),
                     [&](std::size_t i, unsigned slot) { work(owned[i], scratch[slot]); });
}

// Every shape's hexagonal spacing, on every process.
std::vector<double> population_spacings(const std::vector<ShapeParticles>& shapes, std::size_t particles,
                                        ShapeShare& share) {
  std::vector<std::vector<double>> spacing(shapes.size());
  for (const std::size_t k : share.owned()) spacing[k] = {hexagonal_spacing(shapes[k].mesh->area(), particles)};
  share.gather(spacing);
  std::vector<double> spacings;
  for (const std::vector<double>& value : spacing) spacings.push_back(value.front());
  return spacings;
}

// The population's spread: over the shapes, the median of each shape's
// smallest distance between two particles along the surface (two sides of
// a thin part count), in its hexagonal spacings, at most 2. `at` has the owned shapes'
// places, `surfaces` their surfaces; every process gets the same number.
double median_smallest_spacing(const std::vector<const std::vector<SurfaceLocation>*>& at,
                               const std::vector<ShapeSurface*>& surfaces, const std::vector<double>& spacings,
                               ShapeShare& share, std::vector<LookScratch>& scratch) {
  std::vector<std::vector<double>> smallest(at.size());
  for_each_owned(share, scratch, [&](std::size_t k, LookScratch& look) {
    smallest[k] = {closest_surface_pair(*at[k], surfaces[k]->neighbours, 2 * spacings[k], look).spacing / spacings[k]};
  });
  share.gather(smallest);
  std::vector<double> values;
  for (const std::vector<double>& value : smallest) values.push_back(value.front());
  return median(std::move(values));
}

// Soft disks of diameter `spacing`: each pair closer than that, in a straight
// line and perhaps along the surface (`surface`: fingers side by side are
// not), is pushed apart, each by kPush of its overlap. `at`: the particles
// of `points` on the surface, `walk` their mesh's. Two at one place (walks
// toward a fingertip can end both on its vertex) part along an edge of the
// lower index's triangle. Adds the mean overlap (in spacings) to `overlap`.
PointSet sampling_step(const PointSet& points, const std::vector<SurfaceLocation>& at, double spacing,
                       const SurfaceWalk& walk, SurfacePairs& surface, LookScratch& scratch, double& overlap) {
  PointSet step = PointSet::Zero(points.rows(), 3);
  const MatrixRowTree<PointSet> tree(points);
  surface.begin_step(at, scratch);
  double total = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    for (const Eigen::Index j : tree.within(points.row(i), spacing)) {
      if (j == i) continue;
      const Eigen::RowVector3d apart = points.row(i) - points.row(j);
      const double distance = apart.norm();
      if (distance >= spacing) continue;
      if (!surface.may_be_within(std::uint32_t(i), std::uint32_t(j), spacing)) continue;
      Eigen::RowVector3d away;
      if (distance > 0) {
        away = apart / distance;
      } else {
        const Vec3 edge = walk.first_edge_direction(at[std::size_t(std::min(i, j))].triangle);
        away << edge.x, edge.y, edge.z;
        if (i > j) away = -away;
      }
      step.row(i) += kPush * (spacing - distance) * away;
      total += (spacing - distance) / spacing;
    }
  }
  overlap += total / double(points.rows());
  return step;
}

// Every owned shape's particles, each step: the sampling step's push plus
// the weighted step of the correspondence `term`, along the surface, at most
// kLargestStep. `points`: every shape's places before the step, replaced
// by those after it; the mean overlap and correspondence step go into `record`.
void evening_iteration(std::vector<ShapeParticles>& shapes, std::vector<PointSet>& points,
                       const std::vector<SurfaceWalk*>& walks, const std::vector<ShapeSurface*>& surfaces,
                       const std::vector<double>& spacings,
                       const CorrespondenceTerm& term, double weight, ShapeShare& share,
                       std::vector<LookScratch>& scratch, JointRefinementRecord& record) {
  const std::size_t particles = std::size_t(points.front().rows());
  const CorrespondenceSteps pull =
      weight > 0 ? term.steps(points, spacings)
                 : CorrespondenceSteps{std::vector<PointSet>(shapes.size(), PointSet::Zero(Eigen::Index(particles), 3))};
  const std::vector<PointSet>& pulls = pull.steps;
  std::vector<ShapePoints> moved(shapes.size());
  for_each_owned(share, scratch, [&](std::size_t k, LookScratch& look) {
    double overlap = 0;
    const PointSet push =
        sampling_step(points[k], shapes[k].at, spacings[k], *walks[k], surfaces[k]->pairs, look, overlap);
    const double cell_area = std::sqrt(0.75) * spacings[k] * spacings[k];
    const std::vector<Vec3> shut =
        surfaces[k]->holes.pull(shapes[k].at, kHoleReach * spacings[k], cell_area, look.solver);
    for (std::size_t i = 0; i < particles; ++i) {
      SurfaceLocation& at = shapes[k].at[i];
      const Eigen::RowVector3d total = push.row(Eigen::Index(i)) + weight * pulls[k].row(Eigen::Index(i));
      Vec3 move = Vec3{total(0), total(1), total(2)} + kHoleGain * shut[i];
      const Vec3 normal = walks[k]->normal(at.triangle);
      move = move + (-dot(move, normal)) * normal;  // along the surface
      const double length = norm(move), largest = kLargestStep * spacings[k];
      if (length > largest) move = (largest / length) * move;
      if (length > 0) at = walks[k]->walk(at.triangle, at.at + move);
    }
    moved[k] = {positions(shapes[k].at), {overlap}};
  });
  share.gather_points(moved, particles);
  double overlap = 0;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    points[k] = std::move(moved[k].points);
    overlap += moved[k].numbers.front();
  }
  record.overlap.push_back(overlap / double(shapes.size()));
  record.correspondence_step.push_back(pull.mean_length);
}

// One owned shape's packing: its particles, the radius they grow to, and
// the points of its surface that find its holes.
struct ShapePacking {
  PackingRelaxation relaxation;
  RadiusGrowth growth;
  std::unique_ptr<ShapeSurface> surface;
  bool released = false;  // packs on its own: the correspondence step no longer nudges it
  bool active = true;     // packs in this phase
};

// What every process knows of every shape's packing after a round.
struct PackingStatus {
  PointSet points;         // its particles' places
  double target = 0;       // the smallest spacing held
  bool growing = false;    // it runs the next round
  bool released = false;
};

// Every shape's status before round `round`, gathered from the owners.
std::vector<PackingStatus> packing_status(const std::vector<std::optional<ShapePacking>>& packings,
                                          std::size_t particles, std::size_t round, ShapeShare& share) {
  // The numbers: the smallest spacing held, growing, released (1 or 0).
  std::vector<ShapePoints> shapes(packings.size());
  for (const std::size_t k : share.owned()) {
    const ShapePacking& packing = *packings[k];
    const bool growing = packing.active && packing.growth.patient(round);
    shapes[k] = {positions(packing.relaxation.locations()),
                 {packing.growth.target(), growing ? 1.0 : 0.0, packing.released ? 1.0 : 0.0}};
  }
  share.gather_points(shapes, particles);
  std::vector<PackingStatus> status;
  for (ShapePoints& shape : shapes) {
    status.push_back({std::move(shape.points), shape.numbers[0], shape.numbers[1] != 0, shape.numbers[2] != 0});
  }
  return status;
}

// A packing round of every owned shape still growing, each particle
// nudged by kHoleGain times its hole pull and, in a shape not released,
// `weight` times its step of the correspondence `term`. Each shape's round is its own work: the result is
// the same whatever the number of threads and processes. Returns the
// status after the round.
std::vector<PackingStatus> packing_round(std::vector<std::optional<ShapePacking>>& packings,
                                         const std::vector<PackingStatus>& status, std::size_t round,
                                         const std::vector<double>& spacings, const CorrespondenceTerm& term,
                                         double weight, ShapeShare& share, std::vector<LookScratch>& scratch,
                                         JointRefinementRecord& record) {
  const auto nudged = [](const PackingStatus& shape) { return shape.growing && !shape.released; };
  CorrespondenceSteps pull;
  if (weight > 0 && std::any_of(status.begin(), status.end(), nudged)) {
    std::vector<PointSet> points;
    for (const PackingStatus& shape : status) points.push_back(shape.points);
    pull = term.steps(points, spacings);
  }
  const std::vector<PointSet>& pulls = pull.steps;
  for_each_owned(share, scratch, [&](std::size_t k, LookScratch& look) {
    ShapePacking& packing = *packings[k];
    if (!status[k].growing) return;
    const double cell_area = std::sqrt(0.75) * spacings[k] * spacings[k];
    std::vector<Vec3> nudge = packing.surface->holes.pull(packing.relaxation.locations(), kHoleReach * spacings[k],
                                                          cell_area, look.solver);
    for (Vec3& step : nudge) step = kHoleGain * step;
    if (!pulls.empty() && !packing.released) {
      for (Eigen::Index i = 0; i < pulls[k].rows(); ++i) {
        nudge[std::size_t(i)] =
            nudge[std::size_t(i)] + Vec3{weight * pulls[k](i, 0), weight * pulls[k](i, 1), weight * pulls[k](i, 2)};
      }
    }
    const double radius = packing.growth.radius();
    packing.relaxation.push_round(radius, nudge);
    const double spacing = packing.relaxation.smallest_spacing(packing.growth.target());
    if (std::isfinite(spacing)) packing.growth.record(radius, spacing, round);
  });
  std::vector<PackingStatus> after = packing_status(packings, std::size_t(status.front().points.rows()), round + 1, share);
  double spacing_sum = 0;
  for (std::size_t k = 0; k < after.size(); ++k) spacing_sum += after[k].target / spacings[k];
  record.packing_spacing.push_back(spacing_sum / double(after.size()));
  record.packing_correspondence_step.push_back(pull.mean_length);
  return after;
}

// Releases the owned shapes whose packing the correspondence step held
// open: a hole wider than kHeldOpenCover of the shape's spacing. They alone
// pack on, on their own, from round `round`.
void release_held_open(std::vector<std::optional<ShapePacking>>& packings, const std::vector<double>& spacings,
                       std::size_t round, ShapeShare& share) {
  for_each_index(share.owned(), share.threads(), [&](std::size_t k) {
    ShapePacking& packing = *packings[k];
    packing.released = packing.surface->holes.cover(packing.relaxation.locations()) > kHeldOpenCover * spacings[k];
    packing.active = packing.released;
    if (packing.released) packing.growth.renew(round);
  });
}

}  // namespace

void iterate_jointly(std::vector<ShapeParticles>& shapes, std::size_t particles, const JointRefinementOptions& options,
                     ShapeShare& share, JointRefinementRecord& record, bool quiet) {
  if (shapes.size() < 2 || options.iterations == 0) return;
  const std::vector<double> spacings = population_spacings(shapes, particles, share);
  std::vector<std::optional<SurfaceWalk>> own_walks(shapes.size());
  std::vector<SurfaceWalk*> walks(shapes.size(), nullptr);
  std::vector<std::unique_ptr<ShapeSurface>> own_surfaces(shapes.size());
  std::vector<ShapeSurface*> surfaces(shapes.size(), nullptr);
  std::vector<ShapePoints> start(shapes.size());
  for (const std::size_t k : share.owned()) {
    walks[k] = &own_walks[k].emplace(*shapes[k].mesh);
    own_surfaces[k] = std::make_unique<ShapeSurface>(*shapes[k].mesh, kHoleSampleStep * spacings[k]);
    surfaces[k] = own_surfaces[k].get();
    start[k].points = positions(shapes[k].at);
  }
  share.gather_points(start, particles);
  std::vector<PointSet> points;
  for (ShapePoints& shape : start) points.push_back(std::move(shape.points));
  const std::unique_ptr<CorrespondenceTerm> term = correspondence_term(options);
  std::vector<LookScratch> scratch = threads_scratch(share);
  ProgressLine progress("refine", options.iterations, quiet);
  for (std::size_t iteration = 0; iteration < options.iterations; ++iteration) {
    evening_iteration(shapes, points, walks, surfaces, spacings, *term, options.correspondence_weight, share, scratch,
                      record);
    char detail[80];
    std::snprintf(detail, sizeof detail, "overlap %.4f, correspondence step %.4f", record.overlap.back(),
                  record.correspondence_step.back());
    progress.update(iteration + 1, detail);
  }
  progress.finish();
}

void pack_jointly(std::vector<ShapeParticles>& shapes, std::size_t particles, const JointRefinementOptions& options,
                  ShapeShare& share, JointRefinementRecord& record, bool quiet) {
  if (shapes.size() < 2 || options.iterations == 0 || !options.pack) return;
  const std::vector<double> spacings = population_spacings(shapes, particles, share);
  std::vector<std::optional<ShapePacking>> packings(shapes.size());
  for_each_index(share.owned(), share.threads(), [&](std::size_t k) {
    PackingRelaxation relaxation(*shapes[k].mesh, shapes[k].at);
    const double start = relaxation.smallest_spacing(2 * spacings[k]);
    RadiusGrowth growth(std::isfinite(start) ? start : spacings[k], 0, kSmallestGrowth);
    packings[k].emplace(ShapePacking{std::move(relaxation), growth,
                                     std::make_unique<ShapeSurface>(*shapes[k].mesh, kHoleSampleStep * spacings[k])});
  });
  const std::unique_ptr<CorrespondenceTerm> term = correspondence_term(options);
  std::vector<LookScratch> scratch = threads_scratch(share);
  ProgressLine progress("pack", 2 * kPackingRounds, quiet);
  std::size_t round = 1;
  std::vector<PackingStatus> status = packing_status(packings, particles, round, share);
  const auto growing = [](const PackingStatus& shape) { return shape.growing; };
  // Rounds while a shape grows, until round `last`; `round` ends as the round after.
  const auto pack = [&](std::size_t last) {
    for (; round <= last && std::any_of(status.begin(), status.end(), growing); ++round) {
      const double fading = std::max(0.0, 1 - double(round - 1) / double(kFadingRounds));
      const double weight = options.correspondence_weight * std::max(options.packing_hold, fading);
      status = packing_round(packings, status, round, spacings, *term, weight, share, scratch, record);
      char detail[80];
      std::snprintf(detail, sizeof detail, "smallest spacing %.4f d_hex, %zu shapes growing",
                    record.packing_spacing.back(), std::size_t(std::count_if(status.begin(), status.end(), growing)));
      progress.update(round, detail);
    }
  };
  pack(kPackingRounds);
  if (options.correspondence_weight > 0 && options.packing_hold > 0) {
    release_held_open(packings, spacings, round, share);
    status = packing_status(packings, particles, round, share);
    record.packing_released = std::size_t(std::count_if(status.begin(), status.end(), [](const PackingStatus& shape) {
      return shape.released;
    }));
    pack(round + kPackingRounds - 1);
  }
  progress.finish();
  record.packing_rounds = round - 1;
  std::vector<std::vector<SurfaceLocation>> packed(shapes.size());
  std::vector<const std::vector<SurfaceLocation>*> before(shapes.size()), after(shapes.size());
  std::vector<ShapeSurface*> surfaces(shapes.size(), nullptr);
  for (const std::size_t k : share.owned()) {
    surfaces[k] = packings[k]->surface.get();
    packed[k] = packings[k]->relaxation.locations();
    before[k] = &shapes[k].at;
    after[k] = &packed[k];
  }
  // Kept only where it spreads the population at least as well as the iterations did.
  record.packing_undone = median_smallest_spacing(after, surfaces, spacings, share, scratch) <
                          median_smallest_spacing(before, surfaces, spacings, share, scratch);
  if (record.packing_undone) return;
  for (const std::size_t k : share.owned()) shapes[k].at = std::move(packed[k]);
}

double widest_hole_spacings(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& particles) {
  const double spacing = hexagonal_spacing(mesh.area(), particles.size());
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  const SurfaceVoronoi diagram = surface_voronoi(mesh, *solver, particles, scratch);
  const VertexTriangles rings = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  return hole_width(widest_hole(mesh, rings, diagram, particles, kHeldCoverSampleStep * spacing), diagram) / spacing;
}

void hold_back_evening(std::vector<ShapeParticles>& shapes, const std::vector<std::vector<SurfaceLocation>>& transferred,
                       std::size_t particles, double template_hole, const JointRefinementOptions& options,
                       ShapeShare& share, JointRefinementRecord& record) {
  if (options.iterations == 0) {  // no refinement: the transfer's places, as they are
    record.evening_kept.assign(shapes.size(), 1.0);
    record.gap_sweeps.assign(shapes.size(), 0);
    record.hole_swaps.assign(shapes.size(), 0);
    return;
  }
  const std::vector<double> spacings = population_spacings(shapes, particles, share);
  // Every shape's evened places, aligned as the model aligns them: each
  // shape is judged against the mean of the others.
  std::vector<ShapePoints> evened(shapes.size());
  for (const std::size_t k : share.owned()) evened[k].points = positions(shapes[k].at);
  share.gather_points(evened, particles);
  std::vector<PointSet> points;
  for (const ShapePoints& shape : evened) points.push_back(shape.points);
  const ProcrustesAlignment aligned = align_procrustes(points);
  PointSet mean = PointSet::Zero(Eigen::Index(particles), 3);
  for (const PointSet& shape : aligned.aligned) mean += shape;
  const double others = double(shapes.size() - 1);

  std::vector<std::vector<double>> kept(shapes.size());
  for_each_index(share.owned(), share.threads(), [&](std::size_t k) {
    const SurfaceMesh& mesh = *shapes[k].mesh;
    const SurfaceWalk walk(mesh);
    const PointSet others_mean = (mean - aligned.aligned[k]) / others;
    const std::vector<SurfaceLocation>& refined = shapes[k].at;
    ShapeSurface surface(mesh, kHeldCoverSampleStep * spacings[k]);
    LookScratch look;
    const auto cover = [&](const std::vector<SurfaceLocation>& at) { return surface.holes.cover(at); };
    const double refined_cover = cover(refined);
    const auto off_the_others = [&](const std::vector<SurfaceLocation>& at) {
      return (aligned.transforms[k].apply(positions(at)) - others_mean).squaredNorm();
    };
    const double refined_off = off_the_others(refined);
    double share_kept = 1;
    for (std::size_t tenths = 0; tenths < 10; ++tenths) {
      const double fraction = double(tenths) / 10;
      std::vector<SurfaceLocation> held(particles);
      for (std::size_t i = 0; i < particles; ++i) {
        const Vec3 from = transferred[k][i].at, to = refined[i].at;
        held[i] = walk.walk(refined[i].triangle, from + fraction * (to + (-1.0) * from));
      }
      if (closest_surface_pair(held, surface.neighbours, spacings[k], look).spacing < options.even_enough * spacings[k] ||
          cover(held) > kHeldCover * refined_cover ||
          off_the_others(held) > kHeldOffTheOthers * refined_off) {
        continue;
      }
      shapes[k].at = std::move(held);  // `refined` is read no more
      share_kept = fraction;
      break;
    }
    // Still closer than even enough (no share was): moves that only widen
    // a particle's gap along the surface, as the shape's own run makes.
    std::size_t sweeps = 0;
    if (closest_surface_pair(shapes[k].at, surface.neighbours, spacings[k], look).spacing <
        options.even_enough * spacings[k]) {
      SolverScratch scratch;
      const double widest = surface_voronoi(mesh, *surface.solver, shapes[k].at, scratch).cover();
      const EveningLimits limits{kGapSweeps, spacings[k], kGapMinGain * spacings[k], kGapStallGain * spacings[k],
                                 widest, 0, 0};  // no swaps: the shapes' sets stay in correspondence
      EveningOutcome gapped = even_out(mesh, *surface.solver, shapes[k].at, limits, 1, true);
      shapes[k].at = std::move(gapped.points);
      sweeps = gapped.sweeps.size();
    }
    HoleSwapLimits swap_limits;
    swap_limits.max_swaps = std::max(kLeastSwaps, particles / kParticlesPerSwap);
    swap_limits.spacing = options.even_enough * spacings[k];
    swap_limits.cover = kSwapHole * template_hole * spacings[k];
    swap_limits.hole_step = kHeldCoverSampleStep * spacings[k];
    swap_limits.carry_below = kCarryBelow * spacings[k];
    swap_limits.carry_above = kCarryAbove * template_hole * spacings[k];
    swap_limits.steps = kSwapSteps;
    const std::size_t swaps = swap_into_holes(mesh, *surface.solver, surface.neighbours, look, shapes[k].at, swap_limits).swaps;
    kept[k] = {share_kept, double(sweeps), double(swaps)};
  });
  share.gather(kept);
  record.evening_kept.clear();
  record.gap_sweeps.clear();
  record.hole_swaps.clear();
  for (const std::vector<double>& value : kept) {
    record.evening_kept.push_back(value[0]);
    record.gap_sweeps.push_back(std::size_t(value[1]));
    record.hole_swaps.push_back(std::size_t(value[2]));
  }
}

}  // namespace meshparticles
