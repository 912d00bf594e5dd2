// correspondence/shape_share: which shapes a process owns, and what its
// gathers hand every process. One process owns every shape; ranks own
// blocks as even as they can be, which together cover every shape once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <set>
#include <vector>

#include "correspondence/shape_share.hpp"

namespace meshparticles::testing {
namespace {

// Rank `rank` of `processes` as mpi_shape_share makes it, without MPI.
class RankShare : public ShapeShare {
 public:
  RankShare(std::size_t shapes, int rank, int processes) : ShapeShare(shapes, rank, processes, 1) {}
};

TEST(ShapeShare, OneProcessOwnsEveryShapeAndLeads) {
  ShapeShare share(5, 3);
  EXPECT_EQ(share.shapes(), 5u);
  EXPECT_EQ(share.owned(), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_TRUE(share.leads());
  EXPECT_EQ(share.processes(), 1);
  EXPECT_EQ(share.threads(), 3u);
  EXPECT_GE(ShapeShare(2).threads(), 1u);  // 0: every core, at least one
  EXPECT_FALSE(share.owns(5));
}

TEST(ShapeShare, RanksOwnEvenBlocksThatCoverEveryShapeOnce) {
  for (std::size_t shapes : {1u, 2u, 7u, 16u}) {
    for (int processes : {1, 2, 3, 5}) {
      std::multiset<std::size_t> seen;
      std::size_t least = shapes, most = 0;
      for (int rank = 0; rank < processes; ++rank) {
        const RankShare share(shapes, rank, processes);
        EXPECT_EQ(share.leads(), rank == 0);
        const std::vector<std::size_t> owned = share.owned();
        for (std::size_t k = 1; k < owned.size(); ++k) EXPECT_EQ(owned[k], owned[k - 1] + 1) << "a block";
        for (std::size_t k : owned) {
          EXPECT_TRUE(share.owns(k));
          seen.insert(k);
        }
        least = std::min(least, owned.size());
        most = std::max(most, owned.size());
      }
      EXPECT_EQ(seen.size(), shapes) << shapes << " shapes, " << processes << " processes";
      for (std::size_t k = 0; k < shapes; ++k) EXPECT_EQ(seen.count(k), 1u) << "shape " << k;
      EXPECT_LE(most - least, 1u) << shapes << " shapes, " << processes << " processes";
    }
  }
  // 7 over 3: the last rank holds the one more.
  EXPECT_EQ(RankShare(7, 0, 3).owned(), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(RankShare(7, 2, 3).owned(), (std::vector<std::size_t>{4, 5, 6}));
}

// One process: gather_points hands back every shape's points and numbers
// exactly as they were, through the one message of doubles.
TEST(ShapeShare, GatherPointsGivesBackEveryShapeExactly) {
  ShapeShare share(3, 1);
  std::vector<ShapePoints> shapes(3);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    shapes[k].points = PointSet::Random(4, 3) * (1.0 + double(k)) / 3.0;
    shapes[k].numbers = {double(k), 1.0 / 3.0, -0.0};
  }
  const std::vector<ShapePoints> before = shapes;
  share.gather_points(shapes, 4);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    EXPECT_EQ(shapes[k].points, before[k].points) << "shape " << k;
    EXPECT_EQ(shapes[k].numbers, before[k].numbers) << "shape " << k;
  }
}

}  // namespace
}  // namespace meshparticles::testing
