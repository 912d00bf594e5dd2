#include "particles/spacing_relaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "common/parallel_for.hpp"
#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "mesh/point_grid.hpp"
#include "mesh/vertex_normals.hpp"

namespace meshparticles {

namespace {

// The first rounds push for this many hexagonal spacings: every pair closer
// than a little over the mean spacing pushes, so the density evens out and
// no vacancy (a hole a spacing wide) is left for the growing radius to jam
// around (measured on the torus at n = 256: covers of 0.70 to 0.73 after
// it, against 0.78 to 0.84 growing from the sweeps' state directly). At
// 1.1 a vacancy survived on the torus at n = 1,024 (cover 0.85, over the
// limit, so the sweeps were kept); at 1.2 none did, for rho 0.954 there and
// 0.950 to 0.960 elsewhere (1.3: 0.943 to 0.952).
constexpr std::size_t kFoamRounds = 50;
constexpr double kFoamRadius = 1.2;
// The smallest step of the growing radius, a share of the target a round.
// 0.3%, not 0.2% (stop 82): every relaxation kept ran all 150 rounds still
// growing; on the committed meshes at 256 and 1,024, the 46 corpus runs at
// seeds 1 and 2 and the 134k scan, every kept set but one as even or more
// (rho +0.001 to +0.04; fandisk at 256 seed 2 kept one at 0.805 where
// the evening gave 0.822).
constexpr double kSmallestGrowth = 0.003;
// Rounds between candidates (each measures its cover from every vertex: 4%
// of a 100k-vertex run at n = 4,096 when it was every 5 rounds; the kept
// round was the last in every case measured).
constexpr std::size_t kCheckEvery = 25;
// The rounds after which a relaxation that has passed no state more spread
// than its start gives up. Where it is kept (the committed meshes, smooth
// CGAL shapes) a first such state comes by round 100 (knot1 at n = 256:
// at 100, atrium and bear at 75, most by 25); where it is not (most
// real models: parts facing each other through the air), the rounds after
// this were a third of its time, spent for nothing.
constexpr std::size_t kHopelessAfter = 100;
// The even-density rounds are most of the relaxation's time (each pushes
// every particle kPushesPerRound times; a growing round seldom moves one).
// Where they squeeze some pair far under the start's spacing the run is
// not kept. Measured on spread's working mesh (input edges over 0.3 d_hex
// split) over 86 runs (the CGAL models at n = 256 and 1,024 with at least
// 4 vertices a particle, the committed meshes), 43 of which relaxed: the
// widest smallest spacing of rounds 11 to 25 was at least 0.932 of the
// start's where a state more spread came after round 25 (atrium at 256;
// bear 0.987, knot1 1.011 at 256), and under 0.85 of it on 6 of the 19
// that kept none (blade at 256 and 1,024, blobby-shuffled, diplodocus,
// knot, turbine at 256): those stop after round 25 (`squeezed`). At 0.85
// (0.19.0) four more that keep none ran on: dino at 256 (0.890), knot2 at
// 256 (0.873) and lion-head at 1,024 (0.859) to round 51, armadillo at
// 4,096 (0.854) to round 75 (2.9 s of its 7 s run on 2 threads, a third of
// the relaxation thrown away on the corpus benchmark's 46 runs). Measured
// again (0.20.0) on 48 runs that reach round 25 (every CGAL model up to
// 60,000 vertices at n = 256, 1,024 and 4,096 with 4 vertices a particle,
// the committed meshes; 25 kept) and on 20 more seeds of the kept ones:
// every kept run at 0.932 or more (atrium at 256, seeds 1 and 2; the other
// seeds 0.948 to 1.099), every CGAL model's 0.987 or more. So 0.9: 3.5%
// under atrium.
constexpr std::size_t kSqueezeFrom = 11, kSqueezeTo = 25;
constexpr double kSqueezedShare = 0.9;
// And once the radius grows: while no state more spread than the start has
// come, the rounds stop where even the fastest growth (kGrowth a round from
// the widest spacing held) times this margin would not pass the start's
// spacing by kHopelessAfter (`out_of_reach`). On the same 86 runs the
// start's spacing over that bound was at most 0.957 before a first such
// state (fandisk_large at 1,024, at round 100; knot1 at 256 0.953), and
// at least 1.055 at round 51 on the 13 it stops there, all of them that
// kept none and were not squeezed (bunny00 at 256; then knot2 at 256
// 1.116, squeezed since 0.20.0).
constexpr double kReachMargin = 1.05;
// A state more spread than the start is a candidate only within a cover
// limit. While none has come, one whose cover is over the (widest) limit by
// this share stops the rounds (`uncovered`): the pushes have opened holes,
// where parts face each other through the air, that the growing radius does
// not close. Measured at every check of 93 runs (the CGAL models of up to
// 60,000 vertices at n = 256, 1,024 and 4,096 with at least 4 vertices a
// particle, the committed meshes; 30 kept): in every run that kept one,
// the first state more spread than the start was within the limit (0.96 of
// it at most, knot1 at 256), so a candidate; no later check of theirs was
// over 1.05 of it (refined_elephant at 4,096, round 75). Of those that kept
// none, diplodocus at 4,096 was at 1.48 at round 25 (then 1.06, 1.54, 1.52)
// and ran to round 100 for nothing: now its relaxation takes 0.8 to 1.0 s,
// not 2.4. (Armadillo at 4,096, at 1.20 from round 75, stopped there to
// 0.19.0; since 0.20.0 it is squeezed at round 25.)
constexpr double kUncoveredShare = 1.15;

double straight_cover(const SurfaceMesh& mesh, const std::vector<Vec3>& vertex_normal, const std::vector<Vec3>& particles,
                      const std::vector<Vec3>& particle_normals, unsigned threads) {
  if (particles.empty()) return std::numeric_limits<double>::infinity();
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  const auto& positions = mesh.positions();
  // The nearest particle, or where it faces away (a thin sheet's other
  // side), the nearest facing one among the kNearest nearest.
  constexpr std::size_t kNearest = 8;
  const auto facing = [&](VertexId v, std::uint32_t particle) {
    return dot(vertex_normal[v], particle_normals[particle]) >=
           PackingRelaxation::kFacingCosine * norm(vertex_normal[v]) * norm(particle_normals[particle]);
  };
  // The vertices in pieces, each piece's largest: the largest of all, whatever the threads.
  constexpr std::size_t kCoverPiece = 4096;
  std::vector<double> cover(piece_count(mesh.vertex_count(), kCoverPiece), 0.0);
  for_each_piece(mesh.vertex_count(), kCoverPiece, threads, [&](std::size_t piece, std::size_t from, std::size_t to) {
    std::uint32_t nearest[kNearest];
    double squared[kNearest];
    for (VertexId v = VertexId(from); v < to; ++v) {
      const double query[3] = {positions[v].x, positions[v].y, positions[v].z};
      tree.knnSearch(query, 1, nearest, squared);
      double to_nearest = std::sqrt(squared[0]);
      if (!facing(v, nearest[0])) {
        const std::size_t found = tree.knnSearch(query, std::min(kNearest, particles.size()), nearest, squared);
        for (std::size_t k = 0; k < found; ++k) {
          if (facing(v, nearest[k])) {
            to_nearest = std::sqrt(squared[k]);
            break;
          }
        }
      }
      cover[piece] = std::max(cover[piece], to_nearest);
    }
  });
  return cover.empty() ? 0.0 : *std::max_element(cover.begin(), cover.end());
}

}  // namespace

const char* relaxation_stop_name(RelaxationStop stop) {
  switch (stop) {
    case RelaxationStop::not_run: return "not_run";
    case RelaxationStop::max_rounds: return "max_rounds";
    case RelaxationStop::stalled: return "stalled";
    case RelaxationStop::no_candidate: return "no_candidate";
    case RelaxationStop::squeezed: return "squeezed";
    case RelaxationStop::out_of_reach: return "out_of_reach";
    case RelaxationStop::uncovered: return "uncovered";
  }
  return "";
}

bool straight_lines_misjudge(const std::vector<Vec3>& at, double geodesic_spacing, unsigned threads) {
  const double below = kRelaxationStraightShare * geodesic_spacing;
  if (!(below > 0)) return false;
  // Every pair nearer than `below`, in pieces on the threads: any is enough.
  const PointGrid grid(at, below);
  constexpr std::size_t kPiece = 1024;
  std::vector<char> near(piece_count(at.size(), kPiece), 0);
  for_each_piece(at.size(), kPiece, threads, [&](std::size_t piece, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to && !near[piece]; ++i) {
      grid.for_each_within(at[i], below * below, [&](std::uint32_t j) { near[piece] |= char(j != i); });
    }
  });
  return std::find(near.begin(), near.end(), 1) != near.end();
}

const RelaxationCandidate* fallback_state(const RelaxationOutcome& outcome, double widening, double cover_limit) {
  for (auto state = outcome.passed.rbegin(); state != outcome.passed.rend(); ++state) {
    if (state->cover * widening > cover_limit) continue;
    const bool tried = std::any_of(outcome.candidates.begin(), outcome.candidates.end(),
                                   [&](const RelaxationCandidate& c) { return c.round == state->round; });
    return tried ? nullptr : &*state;
  }
  return nullptr;
}

double straight_cover(const SurfaceMesh& mesh, const std::vector<VertexId>& particles) {
  const auto normals = vertex_normals(mesh);
  std::vector<Vec3> at, facing;
  for (const VertexId v : particles) {
    at.push_back(mesh.positions()[v]);
    facing.push_back(normals[v]);
  }
  return straight_cover(mesh, normals, at, facing, 1);
}

RelaxationOutcome relax_spacing(const SurfaceMesh& mesh, const std::vector<VertexId>& start, double d_hex,
                                std::size_t max_rounds, const std::vector<double>& cover_limits,
                                double start_geodesic_cover, bool quiet, double start_geodesic_spacing,
                                bool stop_early, unsigned threads) {
  const auto started = std::chrono::steady_clock::now();
  threads = cores_or(threads);
  PackingRelaxation relaxation(mesh, start, threads);
  RelaxationOutcome outcome;
  const double reach = 2 * d_hex;
  outcome.start_spacing = relaxation.smallest_spacing(reach);
  const std::vector<Vec3> normals = vertex_normals(mesh);
  outcome.start_cover = straight_cover(mesh, normals, relaxation.positions(), relaxation.normals(), threads);
  // Straight covers stand in for geodesic ones scaled as at the start:
  // near tips and seams the facing rule makes a straight cover larger than
  // the geodesic (on 6 CGAL meshes 0.93 to 1.03 against 0.75 to 0.78),
  // elsewhere a little smaller.
  const double to_geodesic = start_geodesic_cover > 0 && outcome.start_cover > 0 && std::isfinite(outcome.start_cover)
                                 ? start_geodesic_cover / outcome.start_cover
                                 : 1.0;
  std::vector<std::vector<PackingRelaxation::Particle>> kept(cover_limits.size(), relaxation.particles());
  std::vector<std::vector<PackingRelaxation::Particle>> passed;  // outcome.passed's particles
  for (const double limit : cover_limits) {
    (void)limit;
    outcome.candidates.push_back({{}, outcome.start_spacing, to_geodesic * outcome.start_cover, 0});
  }
  outcome.skipped_for_straight = max_rounds > 0 && std::isfinite(outcome.start_spacing) &&
                                 straight_lines_misjudge(relaxation.positions(), start_geodesic_spacing, threads);
  if (max_rounds > 0 && std::isfinite(outcome.start_spacing) && !outcome.skipped_for_straight) {
    ProgressLine progress("relax", max_rounds, quiet);
    std::optional<RadiusGrowth> growth;
    // The last round a first candidate can come at.
    const std::size_t horizon = std::min(max_rounds, kHopelessAfter);
    // The widest cover a candidate may have: `uncovered` is judged against it.
    const double widest_limit = cover_limits.empty() ? std::numeric_limits<double>::infinity()
                                                     : *std::max_element(cover_limits.begin(), cover_limits.end());
    outcome.stopped = RelaxationStop::max_rounds;
    double foam_widest = 0;  // the widest smallest spacing of rounds kSqueezeFrom to kSqueezeTo
    for (std::size_t round = 1; round <= max_rounds; ++round) {
      const bool evening = round <= kFoamRounds;
      if (round == kFoamRounds + 1) {  // the growth starts from what the even density reached
        growth.emplace(relaxation.smallest_spacing(reach), round, kSmallestGrowth);
      }
      if (!evening && !growth->patient(round)) {
        outcome.stopped = RelaxationStop::stalled;
        break;
      }
      const bool none_yet = std::all_of(outcome.candidates.begin(), outcome.candidates.end(),
                                        [](const RelaxationCandidate& c) { return c.round == 0; });
      if (none_yet && round > kHopelessAfter) {
        outcome.stopped = RelaxationStop::no_candidate;  // no state yet more spread than the start: it will not be kept
        break;
      }
      if (stop_early && none_yet && round == kSqueezeTo + 1 && foam_widest < kSqueezedShare * outcome.start_spacing) {
        outcome.stopped = RelaxationStop::squeezed;  // the even density squeezed a pair: it will not be kept
        break;
      }
      if (stop_early && none_yet && !evening && round <= horizon &&
          kReachMargin * growth->reachable(horizon - round + 1) <= outcome.start_spacing) {
        outcome.stopped = RelaxationStop::out_of_reach;  // nor can one come by the horizon
        break;
      }
      const double radius = evening ? kFoamRadius * d_hex : growth->radius();
      relaxation.push_round(radius);
      const double spacing = relaxation.smallest_spacing(evening ? radius : growth->target());
      outcome.round_spacings.push_back(spacing);
      if (round >= kSqueezeFrom && round <= kSqueezeTo) foam_widest = std::max(foam_widest, spacing);
      if (!std::isfinite(spacing)) continue;  // no pair within reach: nothing to compare
      if (!evening) growth->record(radius, spacing, round);
      const bool wanted = std::any_of(outcome.candidates.begin(), outcome.candidates.end(),
                                      [&](const RelaxationCandidate& c) { return spacing > c.spacing; });
      if ((round % kCheckEvery == 0 || round == max_rounds) && wanted) {
        const double cover = to_geodesic * straight_cover(mesh, normals, relaxation.positions(), relaxation.normals(), threads);
        if (stop_early && none_yet && cover > kUncoveredShare * widest_limit) {
          outcome.stopped = RelaxationStop::uncovered;  // holes no growth closes: it will not be kept
          break;
        }
        for (std::size_t k = 0; k < cover_limits.size(); ++k) {
          RelaxationCandidate& candidate = outcome.candidates[k];
          if (spacing <= candidate.spacing || cover > cover_limits[k]) continue;
          candidate.spacing = spacing;
          candidate.cover = cover;
          candidate.round = round;
          kept[k] = relaxation.particles();
        }
        const double passed_spacing = outcome.passed.empty() ? outcome.start_spacing : outcome.passed.back().spacing;
        if (spacing > passed_spacing && cover <= widest_limit) {
          outcome.passed.push_back({{}, spacing, cover, round});
          passed.push_back(relaxation.particles());
        }
      }
      const double widest = outcome.candidates.empty() ? spacing : outcome.candidates.front().spacing;
      progress.update(round, "smallest spacing " + format_number("%.4f", widest / d_hex) + " d_hex");
    }
    progress.finish();
  }
  for (std::size_t k = 0; k < kept.size(); ++k) {
    relaxation.restore(kept[k]);
    outcome.candidates[k].points = relaxation.locations();
  }
  for (std::size_t k = 0; k < passed.size(); ++k) {
    relaxation.restore(passed[k]);
    outcome.passed[k].points = relaxation.locations();
  }
  outcome.kept = outcome.candidates.size();
  outcome.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return outcome;
}

}  // namespace meshparticles
