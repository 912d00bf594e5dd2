#include "correspondence/point_tree.hpp"

namespace meshparticles {

PointTree::PointTree(const PointSet& points) : cloud_{&points} {
  tree_ = std::make_unique<Tree>(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree_->buildIndex();
}

std::vector<Eigen::Index> PointTree::nearest(const Eigen::RowVector3d& query, std::size_t count) const {
  count = std::min<std::size_t>(count, std::size_t(cloud_.points->rows()));
  std::vector<std::size_t> indices(count);
  std::vector<double> distances(count);
  const double at[3] = {query(0), query(1), query(2)};
  const std::size_t found = tree_->knnSearch(at, count, indices.data(), distances.data());
  return std::vector<Eigen::Index>(indices.begin(), indices.begin() + std::ptrdiff_t(found));
}

}  // namespace meshparticles
