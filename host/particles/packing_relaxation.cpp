#include "particles/packing_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/parallel_for.hpp"
#include "mesh/point_grid.hpp"
#include "mesh/vertex_normals.hpp"

namespace meshparticles {

namespace {

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
// Each growing round pushes for a radius this share above the target; a
// round that ends below the target halves it, down to the caller's smallest.
constexpr double kGrowth = 0.005;
// The rounds without a gain of kPatienceGain (a share of the spacing) after
// which the growing rounds stop.
constexpr std::size_t kPatienceRounds = 60;
constexpr double kPatienceGain = 1e-4;

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

// The indices of `points` in Morton (Z-curve) order in the mesh's bounding
// box; ties by index.
std::vector<std::uint32_t> morton_order(const SurfaceMesh& mesh, const std::vector<Vec3>& points) {
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
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    keyed.emplace_back(spread_bits(cell(p.x, low.x, high.x)) | spread_bits(cell(p.y, low.y, high.y)) << 1 |
                           spread_bits(cell(p.z, low.z, high.z)) << 2,
                       i);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  for (const auto& [key, i] : keyed) order.push_back(i);
  return order;
}

// Per triangle, the sum of its corners' vertex normals, unit (zero where
// they cancel).
std::vector<Vec3> facing_normals(const SurfaceMesh& mesh) {
  const std::vector<Vec3> at_vertex = vertex_normals(mesh);
  std::vector<Vec3> facing;
  facing.reserve(mesh.triangle_count());
  for (const Triangle& t : mesh.triangles()) {
    const Vec3 sum = at_vertex[t[0]] + at_vertex[t[1]] + at_vertex[t[2]];
    const double length = norm(sum);
    facing.push_back(length > 0 ? (1.0 / length) * sum : Vec3{});
  }
  return facing;
}

// A piece of the work shared among threads, in particles or pairs: large
// enough that taking one costs little, small enough to balance two to 64
// threads at a few thousand particles.
constexpr std::size_t kPushPiece = 256;

}  // namespace

PackingRelaxation::PackingRelaxation(const SurfaceMesh& mesh, const std::vector<VertexId>& start, unsigned threads)
    : walk_(mesh), facing_(facing_normals(mesh)), threads_(std::max(1u, threads)) {
  std::vector<SurfaceLocation> locations;
  for (const VertexId v : start) {
    SurfaceLocation location;
    location.at = mesh.positions()[v];
    location.triangle = walk_.first_triangle(v);
    locations.push_back(location);
  }
  hold(mesh, locations);
}

PackingRelaxation::PackingRelaxation(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& start,
                                     unsigned threads)
    : walk_(mesh), facing_(facing_normals(mesh)), threads_(std::max(1u, threads)) {
  hold(mesh, start);
}

// The particles are held in Morton order of their start (neighbours near in
// memory: on the 1M sphere at n = 100,000 a push in the farthest start's
// order, which scatters them, spent most of its time waiting on memory).
void PackingRelaxation::hold(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& start) {
  std::vector<Vec3> at;
  for (const SurfaceLocation& location : start) at.push_back(location.at);
  order_ = morton_order(mesh, at);
  for (const std::uint32_t i : order_) {
    Particle p;
    p.at = start[i].at;
    p.triangle = start[i].triangle;
    particles_.push_back(p);
  }
}

double PackingRelaxation::smallest_spacing(double reach) {
  if (!(moved_ * 2 < (reach_ - reach))) build_neighbours(std::max(reach, reach_));
  std::vector<double> smallest(piece_count(pairs_.size(), kPushPiece), std::numeric_limits<double>::infinity());
  for_each_piece(pairs_.size(), kPushPiece, threads_, [&](std::size_t piece, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto [i, j] = pairs_[k];
      smallest[piece] = std::min(smallest[piece], distance(particles_[i].at, particles_[j].at));
    }
  });
  return smallest.empty() ? std::numeric_limits<double>::infinity()
                          : *std::min_element(smallest.begin(), smallest.end());
}

bool PackingRelaxation::pair_push(std::uint32_t i, std::uint32_t j, double radius, Vec3& half) const {
  Vec3 apart = particles_[i].at - particles_[j].at;
  const double squared = dot(apart, apart);
  // Far above rounding: a pair this long is not closer than `radius`, and
  // is passed over without a square root.
  if (squared > radius * radius * (1 + 1e-12)) return false;
  const double length = std::sqrt(squared);
  double d = length;
  if (d >= radius) return false;
  if (d == 0) {  // on one point: apart along a direction of i's triangle, the same every time
    apart = tangent(particles_[i].triangle);
    d = 1;
  }
  half = (0.5 * (radius - length) / d) * apart;
  return true;
}

bool PackingRelaxation::sum_over_pairs(double radius, std::vector<Vec3>& shift) const {
  bool any = false;
  Vec3 half;
  for (const auto& [i, j] : pairs_) {
    if (!pair_push(i, j, radius, half)) continue;
    shift[i] = shift[i] + half;
    shift[j] = shift[j] - half;
    any = true;
  }
  return any;
}

bool PackingRelaxation::sum_per_particle(double radius, std::vector<Vec3>& shift) const {
  std::vector<char> pushed(piece_count(particles_.size(), kPushPiece), 0);
  for_each_piece(particles_.size(), kPushPiece, threads_, [&](std::size_t piece, std::size_t from, std::size_t to) {
    bool any = false;
    Vec3 half;
    for (std::uint32_t k = std::uint32_t(from); k < to; ++k) {
      Vec3 sum;
      for (std::uint32_t m = partners_from_[k]; m < partners_above_[k]; ++m) {
        if (!pair_push(partners_[m], k, radius, half)) continue;
        sum = sum - half;
        any = true;
      }
      for (std::uint32_t m = partners_above_[k]; m < partners_from_[k + 1]; ++m) {
        if (!pair_push(k, partners_[m], radius, half)) continue;
        sum = sum + half;
        any = true;
      }
      shift[k] = sum;
    }
    pushed[piece] = any;
  });
  return std::find(pushed.begin(), pushed.end(), 1) != pushed.end();
}

bool PackingRelaxation::push(double radius, const std::vector<Vec3>& nudge) {
  if (!(moved_ * 2 < reach_ - radius)) build_neighbours(kNeighbourReach * radius);
  std::vector<Vec3> shift(particles_.size());
  const bool any = threads_ == 1 ? sum_over_pairs(radius, shift) : sum_per_particle(radius, shift);
  if (!any && nudge.empty()) return false;
  std::vector<double> largest(piece_count(particles_.size(), kPushPiece), 0.0);
  for_each_piece(particles_.size(), kPushPiece, threads_, [&](std::size_t piece, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      Particle& p = particles_[i];
      const Vec3 n = walk_.normal(p.triangle);
      Vec3 step = kStepShare * shift[i] + kMomentum * p.velocity;
      if (!nudge.empty()) step = step + nudge[order_[i]];
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
      largest[piece] = std::max(largest[piece], distance(p.at, at_build_[i]));
    }
  });
  moved_ = largest.empty() ? 0.0 : *std::max_element(largest.begin(), largest.end());
  return any;
}

void PackingRelaxation::push_round(double radius, const std::vector<Vec3>& nudge) {
  if (!push(radius, nudge)) return;
  for (int i = 1; i < kPushesPerRound && push(radius); ++i) {
  }
}

std::vector<Vec3> PackingRelaxation::positions() const {
  std::vector<Vec3> at;
  for (const Particle& p : particles_) at.push_back(p.at);
  return at;
}

std::vector<Vec3> PackingRelaxation::normals() const {
  std::vector<Vec3> normals;
  for (const Particle& p : particles_) normals.push_back(facing(p.triangle));
  return normals;
}

std::vector<SurfaceLocation> PackingRelaxation::locations() const {
  std::vector<SurfaceLocation> locations(particles_.size());
  for (std::size_t k = 0; k < particles_.size(); ++k) {
    const Particle& p = particles_[k];
    locations[order_[k]] = walk_.walk(p.triangle, p.at);
  }
  return locations;
}

// Pairs within `reach`, each once (i < j), in index order.
void PackingRelaxation::build_neighbours(double reach) {
  const std::vector<Vec3> at = positions();
  const PointGrid grid(at, reach);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(piece_count(at.size(), kPushPiece));
  for_each_piece(at.size(), kPushPiece, threads_, [&](std::size_t piece, std::size_t from, std::size_t to) {
    std::vector<std::uint32_t> above;
    for (std::uint32_t i = std::uint32_t(from); i < to; ++i) {
      above.clear();
      grid.for_each_within(at[i], reach * reach, [&](std::uint32_t j) {
        if (j > i) above.push_back(j);
      });
      std::sort(above.begin(), above.end());
      const Vec3 ni = facing(particles_[i].triangle);
      for (const std::uint32_t j : above) {
        if (dot(ni, facing(particles_[j].triangle)) < kFacingCosine) continue;
        found[piece].emplace_back(i, j);
      }
    }
  });
  pairs_.clear();
  for (const auto& piece : found) pairs_.insert(pairs_.end(), piece.begin(), piece.end());
  reach_ = reach;
  moved_ = 0;
  at_build_ = at;
  if (threads_ == 1) return;  // the pushes are summed over the pairs
  // Each particle's partners below it, then those above it, each in index
  // order (the pairs are in index order).
  partners_from_.assign(at.size() + 1, 0);
  partners_above_.assign(at.size(), 0);
  for (const auto& [i, j] : pairs_) {
    ++partners_from_[i + 1];
    ++partners_from_[j + 1];
    ++partners_above_[j];
  }
  for (std::size_t k = 0; k < at.size(); ++k) {
    partners_from_[k + 1] += partners_from_[k];
    partners_above_[k] += partners_from_[k];
  }
  partners_.resize(partners_from_.back());
  std::vector<std::uint32_t> next(partners_from_.begin(), partners_from_.end() - 1);
  for (const auto& [i, j] : pairs_) {
    partners_[next[i]++] = j;
    partners_[next[j]++] = i;
  }
}

RadiusGrowth::RadiusGrowth(double spacing, std::size_t round, double smallest_growth)
    : target_(spacing), growth_(kGrowth), smallest_growth_(smallest_growth), best_(spacing), last_gain_(round) {}

void RadiusGrowth::record(double radius, double spacing, std::size_t round) {
  if (spacing > best_ * (1 + kPatienceGain)) {
    best_ = spacing;
    last_gain_ = round;
  }
  if (spacing < target_) growth_ = std::max(smallest_growth_, growth_ / 2);
  target_ = std::max(target_, std::min(radius, spacing * (1 + growth_)));
}

double RadiusGrowth::reachable(std::size_t rounds) const {
  return std::max(best_, target_) * std::pow(1 + kGrowth, double(rounds));
}

bool RadiusGrowth::patient(std::size_t round) const { return round - last_gain_ <= kPatienceRounds; }

}  // namespace meshparticles
