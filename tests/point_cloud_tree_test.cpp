// mesh/point_cloud_tree: the k-d tree over a PointSet's rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "mesh/point_cloud_tree.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles::testing {
namespace {

// The one k-d tree over a PointSet's rows: the nearest rows, nearest first,
// as a search of every row finds them.
TEST(MatrixRowTree, FindsTheNearestRowsInOrder) {
  std::mt19937_64 random(49);
  std::uniform_real_distribution<double> uniform(-1, 1);
  PointSet points(400, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) points.row(i) << uniform(random), uniform(random), uniform(random);
  const MatrixRowTree<PointSet> tree(points);
  for (int q = 0; q < 20; ++q) {
    const Eigen::RowVector3d query(uniform(random), uniform(random), uniform(random));
    std::vector<std::uint32_t> all(std::size_t(points.rows()));
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    std::sort(all.begin(), all.end(), [&](std::uint32_t a, std::uint32_t b) {
      return (points.row(a) - query).squaredNorm() < (points.row(b) - query).squaredNorm();
    });
    all.resize(8);
    EXPECT_EQ(tree.nearest(query, 8), all);
  }
  EXPECT_EQ(tree.nearest(points.row(7)).front(), 7u);
  EXPECT_EQ(tree.nearest(points.row(0), 1000).size(), 400u);  // no more than there are
}



}  // namespace
}  // namespace meshparticles::testing
