#pragma once
// Particles pushed apart on a surface, all at once: every pair closer than a
// radius moves apart along the surface, with momentum. The rounds of the
// default run's relaxation (spacing_relaxation) and of the correspondence's
// packing (correspondence/joint_refinement) both push this way, so that a
// shape of a population ends as evenly spread as its own run.
//
// Distances are straight lines between particles that face the same way
// (the smoothed normals of their triangles under 120 degrees apart): at a
// spacing the surface is nearly flat, a straight line is never longer than
// the geodesic, and two sides of a thin sheet do not push each other.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/surface_walk.hpp"

namespace meshparticles {

class PackingRelaxation {
 public:
  struct Particle {
    std::uint32_t triangle = 0;
    Vec3 at;
    Vec3 velocity;  // the last move
  };

  // Pairs whose triangles' smoothed normals (facing()) have a cosine under
  // this do not push each other (opposite sides of a thin sheet, 120
  // degrees and more apart).
  static constexpr double kFacingCosine = -0.5;

  // Particles on the vertices `start`, or at surface points. Each push's
  // sums and moves, the smallest spacing and the rebuilds of the pairs run
  // on `threads` threads in fixed pieces: the same bits for any number.
  PackingRelaxation(const SurfaceMesh& mesh, const std::vector<VertexId>& start, unsigned threads = 1);
  PackingRelaxation(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& start, unsigned threads = 1);

  // The smallest spacing over facing pairs within `reach` (infinite where none).
  double smallest_spacing(double reach);

  // Pushes apart the pairs closer than `radius`; false where none is. Each
  // particle's step also takes `nudge` (per particle, in the caller's
  // order; empty: none), a move the caller wants besides the push.
  bool push(double radius, const std::vector<Vec3>& nudge = {});

  // A round: pushes for `radius` until none is closer or kPushesPerRound
  // pushes are done; `nudge` joins the first.
  void push_round(double radius, const std::vector<Vec3>& nudge = {});

  // In the held order (Morton order of the start), for measures over all particles.
  std::vector<Vec3> positions() const;
  std::vector<Vec3> normals() const;  // each particle's facing()

  // In the caller's order.
  std::vector<SurfaceLocation> locations() const;

  const std::vector<Particle>& particles() const { return particles_; }
  void restore(const std::vector<Particle>& particles) {
    particles_ = particles;
    reach_ = 0;
  }

 private:
  void hold(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& start);
  void build_neighbours(double reach);
  // Whether pair (i, j), i < j, is closer than `radius`, and where it is
  // the push it gives i (j gets its opposite).
  bool pair_push(std::uint32_t i, std::uint32_t j, double radius, Vec3& half) const;
  // Each particle's push summed into `shift` in one of two ways that give
  // the same bits: over the pairs in their order (one thread), or each
  // particle over its partners in index order (that order), in pieces on
  // the threads, each pair computed at both ends. False where no pair pushes.
  bool sum_over_pairs(double radius, std::vector<Vec3>& shift) const;
  bool sum_per_particle(double radius, std::vector<Vec3>& shift) const;
  // A unit direction in the plane of `triangle` (its first edge).
  Vec3 tangent(std::uint32_t triangle) const { return walk_.first_edge_direction(triangle); }
  // The way a particle on `triangle` faces: the sum of its corners' vertex
  // normals, unit. Not the triangle's own: a scan's flipped triangle or
  // sliver (igea) would stop its particle pushing the neighbours it
  // touches, and the pair stays a fifth of a spacing closer than the rest.
  Vec3 facing(std::uint32_t triangle) const { return facing_[triangle]; }

  SurfaceWalk walk_;
  std::vector<Vec3> facing_;  // per triangle
  std::vector<std::uint32_t> order_;  // held particle k is the caller's particle order_[k]
  std::vector<Particle> particles_;
  unsigned threads_ = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;  // i < j, in index order
  // Each particle's partners in pairs_, in index order: particle k's are
  // partners_[partners_from_[k]] up to partners_[partners_from_[k + 1]],
  // those above k from partners_above_[k].
  std::vector<std::uint32_t> partners_from_, partners_above_, partners_;
  double reach_ = 0;  // of the pairs
  double moved_ = 0;  // the farthest any particle is from where it was when the pairs were found
  // (the pairs hold every pair closer than reach_ - 2 moved_)
  std::vector<Vec3> at_build_;
};

// The radius of the growing rounds: each round pushes for a radius a little
// above the target, the smallest spacing the rounds have held; a round that
// ends below the target halves the step (soft disks whose radius grows, as
// Lubachevsky and Stillinger grow hard disks into a packing). The rounds
// stop when the smallest spacing has not grown for a while.
class RadiusGrowth {
 public:
  // From the smallest spacing reached so far, at round `round`; a round
  // that ends below the target halves the step, down to `smallest_growth`.
  RadiusGrowth(double spacing, std::size_t round, double smallest_growth);
  double radius() const { return target_ * (1 + growth_); }
  double target() const { return target_; }
  // After a round that pushed for radius() and ended at `spacing`.
  void record(double radius, double spacing, std::size_t round);
  // Whether round `round` should still run: a gain came not long before.
  bool patient(std::size_t round) const;
  // Patient again from round `round`, as if it had just gained.
  void renew(std::size_t round) { last_gain_ = round; }
  // The smallest spacing the growth may reach in `rounds` more rounds: the
  // target rises at most kGrowth a round, from the widest held so far.
  double reachable(std::size_t rounds) const;

 private:
  double target_ = 0, growth_ = 0, smallest_growth_ = 0, best_ = 0;
  std::size_t last_gain_ = 0;
};

}  // namespace meshparticles
