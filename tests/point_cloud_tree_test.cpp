// mesh/point_cloud_tree: the k-d tree over a PointSet's rows; mesh/point_grid
// against it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "mesh/point_cloud_tree.hpp"
#include "mesh/point_grid.hpp"
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



// The grid finds what the k-d tree's radius search finds, point for point:
// random points in a flat box (a surface's particles: most cubes empty), a
// lattice whose neighbours lie exactly at the reach (not within it), and
// a lone point far off (at the smallest reach, more cubes than a key holds
// along an axis: wider cubes).
TEST(PointGrid, FindsWhatTheTreeFinds) {
  std::mt19937_64 random(83);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Vec3> points;
  for (int k = 0; k < 2000; ++k) points.push_back({uniform(random), uniform(random), 0.05 * uniform(random)});
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) points.push_back({2 + 0.125 * i, 2 + 0.125 * j, 0.5});
  }
  points.push_back({40, -40, 7});
  const PointCloud cloud{points};
  const PointCloudTree tree(3, cloud);
  for (const double reach : {1e-5, 0.07, 0.125, 0.3}) {
    const PointGrid grid(points, reach);
    std::size_t pairs = 0;
    for (const Vec3& p : points) {
      std::vector<std::pair<std::uint32_t, double>> near;
      const double query[3] = {p.x, p.y, p.z};
      tree.radiusSearch(query, reach * reach, near, nanoflann::SearchParams(32, 0.0f, false));
      std::vector<std::uint32_t> expected;
      for (const auto& [j, squared] : near) expected.push_back(j);
      std::vector<std::uint32_t> found;
      grid.for_each_within(p, reach * reach, [&](std::uint32_t j) { found.push_back(j); });
      std::sort(expected.begin(), expected.end());
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, expected) << "reach " << reach;
      pairs += found.size();
    }
    EXPECT_GE(pairs, points.size()) << "reach " << reach;  // each point finds itself
    if (reach > 0.05) {
      EXPECT_GT(pairs, 2 * points.size()) << "reach " << reach;
    }
  }
}

}  // namespace
}  // namespace meshparticles::testing
