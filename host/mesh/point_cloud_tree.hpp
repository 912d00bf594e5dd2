#pragma once
// nanoflann's k-d tree over a set of points: a vector of points (mesh
// vertices, particles) or the rows of a three-column matrix (an Eigen
// PointSet, as correspondence holds its shapes): nearest-point and radius
// searches.
#include <algorithm>
#include <cstddef>
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

// The rows of a matrix of three columns as nanoflann's adaptor reads them
// (the matrix must outlive the tree).
template <typename Matrix>
struct MatrixRows {
  const Matrix& points;
  std::size_t kdtree_get_point_count() const { return std::size_t(points.rows()); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const {
    return points(typename Matrix::Index(i), typename Matrix::Index(axis));
  }
  template <typename Box>
  bool kdtree_get_bbox(Box& /*unused*/) const {
    return false;
  }
};

template <typename Cloud>
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3, std::uint32_t>;
using PointCloudTree = KdTree<PointCloud>;

// A tree over the rows of a matrix, holding its adaptor, with the searches
// correspondence asks of it.
template <typename Matrix>
class MatrixRowTree {
 public:
  explicit MatrixRowTree(const Matrix& points) : rows_{points}, tree_(3, rows_) {}
  MatrixRowTree(const MatrixRowTree&) = delete;  // the tree reads rows_ where it is
  MatrixRowTree& operator=(const MatrixRowTree&) = delete;

  // The `count` nearest rows to `query` (nearest first; ties: as the tree
  // returns them, which is deterministic for the same points).
  template <typename Row>
  std::vector<std::uint32_t> nearest(const Row& query, std::size_t count = 1) const {
    count = std::min(count, rows_.kdtree_get_point_count());
    std::vector<std::uint32_t> indices(count);
    std::vector<double> squared(count);
    const double at[3] = {query(0), query(1), query(2)};
    const std::size_t found = tree_.knnSearch(at, count, indices.data(), squared.data());
    return std::vector<std::uint32_t>(indices.begin(), indices.begin() + std::ptrdiff_t(found));
  }

  // Every row closer than `radius` to `query`, in increasing index.
  template <typename Row>
  std::vector<std::uint32_t> within(const Row& query, double radius) const {
    std::vector<std::pair<std::uint32_t, double>> near;
    const double at[3] = {query(0), query(1), query(2)};
    tree_.radiusSearch(at, radius * radius, near, nanoflann::SearchParams(32, 0.0f, false));
    std::vector<std::uint32_t> indices;
    for (const auto& [index, squared] : near) {
      if (squared < radius * radius) indices.push_back(index);
    }
    std::sort(indices.begin(), indices.end());
    return indices;
  }

 private:
  MatrixRows<Matrix> rows_;
  KdTree<MatrixRows<Matrix>> tree_;
};

}  // namespace meshparticles
