#pragma once
// Points binned into cubes: every point within a reach of another, found
// by looking at the 27 cubes around it. The relaxation's pairs are made
// anew every few pushes; a k-d tree's radius searches (mesh/point_cloud_tree)
// were a fifth to a third of the relaxation, its build on one thread.
//
// The points found are those nanoflann's search finds: the squared distance
// is summed as its L2 adaptor sums it (x, then y, then z) and compared with
// `<`, so a list made either way holds the same pairs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "mesh/vec3.hpp"

namespace meshparticles {

class PointGrid {
 public:
  // The points must outlive the grid; `reach` > 0.
  PointGrid(const std::vector<Vec3>& points, double reach) : points_(points) {
    low_ = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 high = -1.0 * low_;
    for (const Vec3& p : points) {
      low_ = {std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    // A cube a hair over the reach: two points nearer than the reach stay in
    // neighbouring cubes whatever the rounding of their cube's index; and
    // no more cubes along an axis than a key holds.
    const double extent = points.empty() ? 0.0 : std::max({high.x - low_.x, high.y - low_.y, high.z - low_.z});
    side_ = std::max(reach * (1 + 1e-9), extent / double(kMostCubes));
    keyed_.reserve(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) keyed_.emplace_back(key(cube(points[i])), i);
    std::sort(keyed_.begin(), keyed_.end());
  }

  // Calls found(j) for every point j with squared distance under
  // `squared_reach` (at most the reach's square) from `p`, in no set order.
  template <typename Found>
  void for_each_within(const Vec3& p, double squared_reach, Found&& found) const {
    const Cube c = cube(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::int64_t x = c.x + dx, y = c.y + dy;
        if (x < 0 || y < 0 || x > kMostCubes || y > kMostCubes) continue;
        // The column's three cubes are one run of keys.
        const std::uint64_t first = key({x, y, std::max<std::int64_t>(c.z - 1, 0)});
        const std::uint64_t last = key({x, y, std::min<std::int64_t>(c.z + 1, kMostCubes)});
        auto at = std::lower_bound(keyed_.begin(), keyed_.end(), std::pair<std::uint64_t, std::uint32_t>(first, 0));
        for (; at != keyed_.end() && at->first <= last; ++at) {
          const Vec3& q = points_[at->second];
          double squared = 0;
          for (const double difference : {p.x - q.x, p.y - q.y, p.z - q.z}) squared += difference * difference;
          if (squared < squared_reach) found(at->second);
        }
      }
    }
  }

 private:
  static constexpr std::int64_t kMostCubes = (std::int64_t(1) << 20) - 1;  // a key's 21 bits an axis, one spare
  struct Cube {
    std::int64_t x, y, z;
  };
  Cube cube(const Vec3& p) const {
    const auto along = [&](double value, double from) {
      return std::clamp<std::int64_t>(std::int64_t(std::floor((value - from) / side_)), 0, kMostCubes);
    };
    return {along(p.x, low_.x), along(p.y, low_.y), along(p.z, low_.z)};
  }
  static std::uint64_t key(const Cube& c) {
    return std::uint64_t(c.x) << 42 | std::uint64_t(c.y) << 21 | std::uint64_t(c.z);
  }

  const std::vector<Vec3>& points_;
  Vec3 low_;
  double side_ = 1;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed_;  // each point's cube key, sorted
};

}  // namespace meshparticles
