#include "particles/spacing_relaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "mesh/surface_walk.hpp"

namespace meshparticles {

namespace {

// Pairs whose triangles' normals have a cosine under this do not push each
// other (opposite sides of a thin sheet, 120 degrees and more apart).
constexpr double kFacingCosine = -0.5;
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
// Then each round pushes for a radius this share above the target; a round
// that ends below the target halves it, down to kSmallestGrowth.
constexpr double kGrowth = 0.005;
constexpr double kSmallestGrowth = 0.002;
// Pushes a round at most. A push moves each particle by kStepShare of half
// the overlap of each pair it is in, plus kMomentum of its last move (heavy
// ball: measured on the sphere at n = 1,024, momentum 0.8 reaches in 100
// rounds the spacing plain pushes reach in 400), along the surface, at most
// a quarter of the radius.
constexpr int kPushesPerRound = 10;
constexpr double kStepShare = 0.9;
constexpr double kMomentum = 0.8;
// The neighbour lists hold the pairs within this many radii, rebuilt when
// two particles may have closed the margin between them (each moved half
// of it from where it was when the pairs were found).
constexpr double kNeighbourReach = 1.5;
// Rounds between candidates (each measures its cover from every vertex: 4%
// of a 100k-vertex run at n = 4,096 when it was every 5 rounds; the kept
// round was the last in every case measured), and the rounds without a gain
// of kPatienceGain (a share of the spacing) after which the rounds stop.
constexpr std::size_t kCheckEvery = 25;
constexpr std::size_t kPatienceRounds = 60;
constexpr double kPatienceGain = 1e-4;

struct Particle {
  std::uint32_t triangle = 0;
  Vec3 at;
  Vec3 velocity;       // the last move
  bool fixed = false;  // on a vertex in no triangle: it stays
};

// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1FFFFF;
  x = (x | x << 32) & 0x1F00000000FFFF;
  x = (x | x << 16) & 0x1F0000FF0000FF;
  x = (x | x << 8) & 0x100F00F00F00F00F;
  x = (x | x << 4) & 0x10C30C30C30C30C3;
  x = (x | x << 2) & 0x1249249249249249;
  return x;
}

// The particles' indices in Morton (Z-curve) order of their vertices in
// the mesh's bounding box; ties by index.
std::vector<std::uint32_t> morton_order(const SurfaceMesh& mesh, const std::vector<VertexId>& start) {
  Vec3 low{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 high = -1.0 * low;
  for (const Vec3& p : mesh.positions()) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const auto cell = [](double value, double from, double to) {
    const double share = to > from ? (value - from) / (to - from) : 0;
    return std::uint64_t(std::clamp(share, 0.0, 1.0) * double(0x1FFFFF));
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  for (std::uint32_t i = 0; i < start.size(); ++i) {
    const Vec3& p = mesh.positions()[start[i]];
    keyed.emplace_back(spread_bits(cell(p.x, low.x, high.x)) | spread_bits(cell(p.y, low.y, high.y)) << 1 |
                           spread_bits(cell(p.z, low.z, high.z)) << 2,
                       i);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  for (const auto& [key, i] : keyed) order.push_back(i);
  return order;
}

class Relaxation {
 public:
  // The particles are held in Morton order of their start (neighbours near
  // in memory: on the 1M sphere at n = 100,000 a push in the farthest
  // start's order, which scatters them, spent most of its time waiting on
  // memory); points() gives them back in the caller's order.
  Relaxation(const SurfaceMesh& mesh, const std::vector<VertexId>& start) : walk_(mesh), order_(morton_order(mesh, start)) {
    for (const std::uint32_t i : order_) {
      Particle p;
      p.at = mesh.positions()[start[i]];
      p.fixed = !walk_.first_triangle(start[i], p.triangle);
      particles_.push_back(p);
    }
  }

  // The smallest spacing over facing pairs within `reach` (infinite where none).
  double smallest_spacing(double reach) {
    if (!(moved_ * 2 < (reach_ - reach))) build_neighbours(std::max(reach, reach_));
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& [i, j] : pairs_) smallest = std::min(smallest, distance(particles_[i].at, particles_[j].at));
    return smallest;
  }

  // Pushes apart the pairs closer than `radius`; false where none is.
  bool push(double radius) {
    if (!(moved_ * 2 < reach_ - radius)) build_neighbours(kNeighbourReach * radius);
    std::vector<Vec3> shift(particles_.size());
    bool any = false;
    for (const auto& [i, j] : pairs_) {
      Vec3 apart = particles_[i].at - particles_[j].at;
      double d = norm(apart);
      if (d >= radius) continue;
      if (d == 0) {  // on one point: apart along a direction of i's triangle, the same every time
        apart = tangent(particles_[i].triangle);
        d = 1;
      }
      const Vec3 half = (0.5 * (radius - norm(particles_[i].at - particles_[j].at)) / d) * apart;
      shift[i] = shift[i] + half;
      shift[j] = shift[j] - half;
      any = true;
    }
    if (!any) return false;
    double largest = 0;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      Particle& p = particles_[i];
      if (p.fixed) continue;
      const Vec3 n = walk_.normal(p.triangle);
      Vec3 step = kStepShare * shift[i] + kMomentum * p.velocity;
      step = step - dot(step, n) * n;
      const double length = norm(step);
      if (length > radius / 4) step = (radius / 4 / length) * step;  // no jump past a neighbour
      p.velocity = step;
      if (length > 0) {
        const SurfaceLocation moved = walk_.walk(p.triangle, p.at + step);
        p.triangle = moved.triangle;
        p.at = moved.at;
      }
      // Every particle's, moved this push or not: one that moved earlier
      // and stopped may still be the farthest from where the pairs were found.
      largest = std::max(largest, distance(p.at, at_build_[i]));
    }
    moved_ = largest;
    return true;
  }

  // A unit direction in the plane of `triangle` (its first edge).
  Vec3 tangent(std::uint32_t triangle) const { return walk_.first_edge_direction(triangle); }

  std::vector<Vec3> positions() const {
    std::vector<Vec3> at;
    for (const Particle& p : particles_) at.push_back(p.at);
    return at;
  }
  std::vector<Vec3> normals() const {
    std::vector<Vec3> normals;
    for (const Particle& p : particles_) normals.push_back(p.fixed ? Vec3{} : walk_.normal(p.triangle));
    return normals;
  }
  std::vector<std::optional<TrianglePoint>> points() const {
    std::vector<std::optional<TrianglePoint>> points(particles_.size());
    for (std::size_t k = 0; k < particles_.size(); ++k) {
      const Particle& p = particles_[k];
      if (!p.fixed) points[order_[k]] = TrianglePoint{p.triangle, walk_.walk(p.triangle, p.at).weights};
    }
    return points;
  }
  const std::vector<Particle>& particles() const { return particles_; }
  void restore(const std::vector<Particle>& particles) {
    particles_ = particles;
    reach_ = 0;
  }

 private:
  // Pairs within `reach`, each once (i < j), in index order.
  void build_neighbours(double reach) {
    const std::vector<Vec3> at = positions();
    const PointCloud cloud{at};
    const PointCloudTree tree(3, cloud);
    pairs_.clear();
    std::vector<std::pair<std::uint32_t, double>> near;
    const nanoflann::SearchParams unsorted(32, 0.0f, false);
    for (std::uint32_t i = 0; i < at.size(); ++i) {
      if (particles_[i].fixed) continue;
      const double query[3] = {at[i].x, at[i].y, at[i].z};
      tree.radiusSearch(query, reach * reach, near, unsorted);
      std::sort(near.begin(), near.end());
      const Vec3 ni = walk_.normal(particles_[i].triangle);
      for (const auto& [j, squared] : near) {
        if (j <= i || particles_[j].fixed) continue;
        if (dot(ni, walk_.normal(particles_[j].triangle)) < kFacingCosine) continue;
        pairs_.emplace_back(i, j);
      }
    }
    reach_ = reach;
    moved_ = 0;
    at_build_ = at;
  }

  SurfaceWalk walk_;
  std::vector<std::uint32_t> order_;  // held particle k is the caller's particle order_[k]
  std::vector<Particle> particles_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
  double reach_ = 0;  // of the pairs
  double moved_ = 0;  // the farthest any particle is from where it was when the pairs were found
  // (the pairs hold every pair closer than reach_ - 2 moved_)
  std::vector<Vec3> at_build_;
};

}  // namespace

namespace {

// Per vertex, the sum of its triangles' area-weighted normals.
std::vector<Vec3> vertex_normals(const SurfaceMesh& mesh) {
  const auto& positions = mesh.positions();
  std::vector<Vec3> normals(mesh.vertex_count());
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 n = cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
    for (const VertexId v : t) normals[v] = normals[v] + n;
  }
  return normals;
}

double straight_cover(const SurfaceMesh& mesh, const std::vector<Vec3>& vertex_normal, const std::vector<Vec3>& particles,
                      const std::vector<Vec3>& particle_normals) {
  if (particles.empty()) return std::numeric_limits<double>::infinity();
  const PointCloud cloud{particles};
  const PointCloudTree tree(3, cloud);
  const auto& positions = mesh.positions();
  // The nearest particle, or where it faces away (a thin sheet's other
  // side), the nearest facing one among the kNearest nearest.
  constexpr std::size_t kNearest = 8;
  std::uint32_t nearest[kNearest];
  double squared[kNearest];
  const auto facing = [&](VertexId v, std::uint32_t particle) {
    return dot(vertex_normal[v], particle_normals[particle]) >=
           kFacingCosine * norm(vertex_normal[v]) * norm(particle_normals[particle]);
  };
  double cover = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
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
    cover = std::max(cover, to_nearest);
  }
  return cover;
}

}  // namespace

double straight_cover(const SurfaceMesh& mesh, const std::vector<VertexId>& particles) {
  const auto normals = vertex_normals(mesh);
  std::vector<Vec3> at, facing;
  for (const VertexId v : particles) {
    at.push_back(mesh.positions()[v]);
    facing.push_back(normals[v]);
  }
  return straight_cover(mesh, normals, at, facing);
}

RelaxationOutcome relax_spacing(const SurfaceMesh& mesh, const std::vector<VertexId>& start, double d_hex,
                                std::size_t max_rounds, const std::vector<double>& cover_limits,
                                double start_geodesic_cover, bool quiet) {
  const auto started = std::chrono::steady_clock::now();
  Relaxation relaxation(mesh, start);
  RelaxationOutcome outcome;
  const double reach = 2 * d_hex;
  outcome.start_spacing = relaxation.smallest_spacing(reach);
  const std::vector<Vec3> normals = vertex_normals(mesh);
  outcome.start_cover = straight_cover(mesh, normals, relaxation.positions(), relaxation.normals());
  // Straight covers stand in for geodesic ones scaled as at the start:
  // near tips and seams the facing rule makes a straight cover larger than
  // the geodesic (on 6 CGAL meshes 0.93 to 1.03 against 0.75 to 0.78),
  // elsewhere a little smaller.
  const double to_geodesic = start_geodesic_cover > 0 && outcome.start_cover > 0 && std::isfinite(outcome.start_cover)
                                 ? start_geodesic_cover / outcome.start_cover
                                 : 1.0;
  std::vector<std::vector<Particle>> kept(cover_limits.size(), relaxation.particles());
  for (const double limit : cover_limits) {
    (void)limit;
    outcome.candidates.push_back({{}, outcome.start_spacing, to_geodesic * outcome.start_cover, 0});
  }
  if (max_rounds > 0 && std::isfinite(outcome.start_spacing)) {
    ProgressLine progress("relax", max_rounds, quiet);
    double target = 0, growth = kGrowth, best = 0;
    std::size_t last_gain = 0;
    for (std::size_t round = 1; round <= max_rounds; ++round) {
      const bool evening = round <= kFoamRounds;
      if (round == kFoamRounds + 1) {  // the growth starts from what the even density reached
        target = best = relaxation.smallest_spacing(target > 0 ? target : reach);
        last_gain = round;
      }
      if (!evening && round - last_gain > kPatienceRounds) break;
      const double radius = evening ? kFoamRadius * d_hex : target * (1 + growth);
      for (int i = 0; i < kPushesPerRound && relaxation.push(radius); ++i) {
      }
      const double spacing = relaxation.smallest_spacing(evening ? radius : target);
      outcome.round_spacings.push_back(spacing);
      if (!std::isfinite(spacing)) continue;  // no pair within reach: nothing to compare
      if (!evening) {
        if (spacing > best * (1 + kPatienceGain)) {
          best = spacing;
          last_gain = round;
        }
        if (spacing < target) growth = std::max(kSmallestGrowth, growth / 2);
        target = std::max(target, std::min(radius, spacing * (1 + growth)));
      }
      const bool wanted = std::any_of(outcome.candidates.begin(), outcome.candidates.end(),
                                      [&](const RelaxationCandidate& c) { return spacing > c.spacing; });
      if ((round % kCheckEvery == 0 || round == max_rounds) && wanted) {
        const double cover = to_geodesic * straight_cover(mesh, normals, relaxation.positions(), relaxation.normals());
        for (std::size_t k = 0; k < cover_limits.size(); ++k) {
          RelaxationCandidate& candidate = outcome.candidates[k];
          if (spacing <= candidate.spacing || cover > cover_limits[k]) continue;
          candidate.spacing = spacing;
          candidate.cover = cover;
          candidate.round = round;
          kept[k] = relaxation.particles();
        }
      }
      const double widest = outcome.candidates.empty() ? spacing : outcome.candidates.front().spacing;
      progress.update(round, "smallest spacing " + format_number("%.4f", widest / d_hex) + " d_hex");
    }
    progress.finish();
  }
  for (std::size_t k = 0; k < kept.size(); ++k) {
    relaxation.restore(kept[k]);
    outcome.candidates[k].points = relaxation.points();
  }
  outcome.kept = outcome.candidates.size();
  outcome.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return outcome;
}

}  // namespace meshparticles
