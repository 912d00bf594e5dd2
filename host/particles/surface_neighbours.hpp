#pragma once
// Whether two particles close in a straight line are close along the
// surface too. Two fingers side by side, an arm resting on the torso, the
// two sides of a fold: their particles are a fraction of a spacing apart
// through the air and several along the surface, and pushing them apart
// empties the fingertips and crowds the palm (FAUST's people at n = 256:
// the closest pairs and the widest holes all at the hands).
//
// From one particle the surface is marched (fast marching from its
// triangle's corners) a little past a radius; another particle's distance
// along the surface is then bounded below by its triangle's corners:
// for each corner c, d(c) - |c - particle| (the path to the particle and
// on to c is no shorter than the path to c). A pair whose bound reaches
// the radius is surely farther along the surface; one under it may not be.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// The working memory of looks along a surface, clean between looks but for
// the last look's answers: a thread's, lent to every shape it looks along in
// turn (as the solver's scratch is), not one per shape held through a whole
// refinement (correspondence/joint_refinement).
struct LookScratch {
  SolverScratch solver;
  std::vector<std::pair<VertexId, float>> within;  // the last look's vertices
  std::vector<float> distance;  // per vertex: the last look's distance, +inf beyond it
  double marched = 0;           // the last look's radius
};

class SurfaceNeighbours {
 public:
  // `mesh` and `solver` (built for it) must outlive this.
  SurfaceNeighbours(const SurfaceMesh& mesh, const GeodesicSolver& solver);

  // Marches from `from` far enough to tell, for any point, whether it lies
  // within `radius` along the surface; the answers stay in `scratch`.
  void look_from(const SurfaceLocation& from, double radius, LookScratch& scratch) const;

  // A lower bound of the distance along the surface from the last look's
  // point (in `scratch`, a look along this surface) to `to`: `radius` or
  // more where `to` is surely not within it.
  double at_least(const SurfaceLocation& to, const LookScratch& scratch) const;

 private:
  const SurfaceMesh& mesh_;
  const GeodesicSolver& solver_;
  double longest_edge_ = 0;
};

// The closest two of `at` along the surface, as far as looks tell: each
// pair within `reach` in a straight line, at the longer of that line and
// the surface's lower bound (so fingers side by side count at their
// distance along the hand); `spacing` is `reach` where none is nearer.
struct ClosestPair {
  double spacing = 0;
  std::uint32_t a = 0, b = 0;  // a < b where `spacing` < `reach`
};
ClosestPair closest_surface_pair(const std::vector<SurfaceLocation>& at, const SurfaceNeighbours& surface, double reach,
                                 LookScratch& scratch);

// The same question asked of a set of particles step after step, as they
// move a little each step: what a look from particle i said of particle j
// is kept, and a pair surely apart stays so while its bound, less how far
// both have moved since, still says so. A pair never looked at, or one no
// longer surely apart, has i looked from anew; every particle is looked
// from anew every kFreshSteps steps. A pair once found perhaps within
// stays so until then (to part along the surface while near in a straight
// line takes longer). Deterministic: the same places give the same answers.
class SurfacePairs {
 public:
  static constexpr std::size_t kFreshSteps = 10;

  SurfacePairs(const SurfaceMesh& mesh, const GeodesicSolver& solver) : look_(mesh, solver) {}

  // A step over the particles `at`, its looks made in `scratch` (both must
  // outlive the step's questions).
  void begin_step(const std::vector<SurfaceLocation>& at, LookScratch& scratch);

  // Whether particle j may lie within `radius` of particle i along the
  // surface (`radius` the same at every step).
  bool may_be_within(std::uint32_t i, std::uint32_t j, double radius);

 private:
  struct Seen {
    std::uint32_t particle = 0;
    Vec3 at;           // its place at the look
    double bound = 0;  // the look's lower bound of its distance
  };
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  SurfaceNeighbours look_;
  const std::vector<SurfaceLocation>* at_ = nullptr;
  LookScratch* scratch_ = nullptr;  // the step's
  std::size_t step_ = 0;
  std::uint32_t looking_ = kNone;  // the particle look_ marched from this step
  std::vector<std::size_t> looked_step_;  // per particle: the step of its last look (+1; 0: never)
  std::vector<Vec3> looked_from_;         // per particle: its place then
  std::vector<std::vector<Seen>> seen_;   // per particle: what that look said of the others asked of
};

}  // namespace meshparticles
