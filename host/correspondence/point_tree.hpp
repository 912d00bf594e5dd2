#pragma once
// Nearest points of a point set (nanoflann's k-d tree over a PointSet):
// what the alignment's closest-point pairs and the particle transfer ask.
#include <memory>
#include <utility>
#include <vector>

#include <nanoflann.hpp>

#include "shape_model/point_sets.hpp"

namespace meshparticles {

class PointTree {
 public:
  explicit PointTree(const PointSet& points);
  // The `count` nearest points to `query` (nearest first; ties: as the tree
  // returns them, which is deterministic for the same points).
  std::vector<Eigen::Index> nearest(const Eigen::RowVector3d& query, std::size_t count = 1) const;

 private:
  struct Cloud {
    const PointSet* points;
    std::size_t kdtree_get_point_count() const { return std::size_t(points->rows()); }
    double kdtree_get_pt(std::size_t i, std::size_t axis) const { return (*points)(Eigen::Index(i), Eigen::Index(axis)); }
    template <typename Box>
    bool kdtree_get_bbox(Box& /*unused*/) const {
      return false;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3, std::size_t>;
  Cloud cloud_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace meshparticles
