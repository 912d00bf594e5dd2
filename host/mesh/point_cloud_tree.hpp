#pragma once
// nanoflann's k-d tree over a vector of points (mesh vertices, particles):
// nearest-point and radius searches.
#include <cstdint>
#include <vector>

#include <nanoflann.hpp>

#include "mesh/vec3.hpp"

namespace meshparticles {

// The points as nanoflann's adaptor reads them (the vector must outlive the tree).
struct PointCloud {
  const std::vector<Vec3>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const {
    const Vec3& p = points[i];
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  }
  template <typename Box>
  bool kdtree_get_bbox(Box& /*unused*/) const {
    return false;  // the tree computes it
  }
};

using PointCloudTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 3, std::uint32_t>;

}  // namespace meshparticles
