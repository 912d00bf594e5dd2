// correspondence/joint_refinement: the iterations, the packing and the
// hold-back on three small shapes (one sphere's mesh stretched three ways,
// so that row i starts on the same vertex of each). Every place stays on
// its shape's surface; the iterations even the crowded start out; the
// result is the same to the bit whatever the threads; the packing is kept
// only where it spreads the shapes at least as well; the hold-back keeps a
// share of each shape's evening in tenths, and a shape still under
// even-enough takes sweeps that only widen its gaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "correspondence/joint_refinement.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/midpoint_refinement.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles::testing {
namespace {

constexpr std::size_t kTransferredParticles = 40;
// The template's widest hole that hold_back_evening holds the shapes to:
// none here, so that only a closest pair under even enough moves a particle
// into a hole (the holes' own swaps: hole_swap_test).
constexpr double kNoHoleLimit = std::numeric_limits<double>::infinity();

class JointRefinement : public ::testing::Test {
 protected:
  void SetUp() override {
    const SurfaceMesh sphere = generate_mesh_at("sphere", 400);
    for (double stretch : {1.0, 1.3, 0.8}) {
      std::vector<Vec3> positions = sphere.positions();
      for (Vec3& p : positions) p.x *= stretch;
      meshes_.emplace_back(positions, sphere.triangles());
    }
    // The vertices nearest the pole: a crowded start, the same rows on every shape.
    std::vector<std::size_t> ids(sphere.vertex_count());
    for (std::size_t v = 0; v < ids.size(); ++v) ids[v] = v;
    std::sort(ids.begin(), ids.end(), [&](std::size_t a, std::size_t b) {
      return sphere.positions()[a].z > sphere.positions()[b].z || (sphere.positions()[a].z == sphere.positions()[b].z && a < b);
    });
    ids.resize(kTransferredParticles);
    for (const SurfaceMesh& mesh : meshes_) {
      const std::vector<SurfaceLocation> vertices = vertex_locations(mesh);
      ShapeParticles& shape = start_.emplace_back();
      shape.mesh = &mesh;
      for (std::size_t v : ids) shape.at.push_back(vertices[v]);
    }
  }

  std::vector<ShapeParticles> iterated(const JointRefinementOptions& options, unsigned threads,
                                       JointRefinementRecord& record) const {
    std::vector<ShapeParticles> shapes = start_;
    ShapeShare share(shapes.size(), threads);
    iterate_jointly(shapes, kTransferredParticles, options, share, record, true);
    return shapes;
  }

  // The places after options.iterations iterations stand for the transfer's;
  // as many more refine them; then each shape is held back from the
  // refinement's places toward the transfer's.
  struct HeldBack {
    std::vector<ShapeParticles> refined, shapes;
  };
  HeldBack held_back(const JointRefinementOptions& options, JointRefinementRecord& record) const {
    const std::vector<ShapeParticles> transfer = iterated(options, 2, record);
    std::vector<ShapeParticles> shapes = transfer;
    ShapeShare share(shapes.size(), 2);
    iterate_jointly(shapes, kTransferredParticles, options, share, record, true);
    const std::vector<ShapeParticles> refined = shapes;
    std::vector<std::vector<SurfaceLocation>> transferred;
    for (const ShapeParticles& shape : transfer) transferred.push_back(shape.at);
    hold_back_evening(shapes, transferred, kTransferredParticles, kNoHoleLimit, options, share, record);
    return {refined, std::move(shapes)};
  }

  static double smallest_spacing(const ShapeParticles& shape) {
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < shape.at.size(); ++i) {
      for (std::size_t j = i + 1; j < shape.at.size(); ++j) smallest = std::min(smallest, norm(shape.at[i].at + (-1.0) * shape.at[j].at));
    }
    return smallest / hexagonal_spacing(shape.mesh->area(), kTransferredParticles);
  }
  static double median_smallest_spacing(const std::vector<ShapeParticles>& shapes) {
    std::vector<double> values;
    for (const ShapeParticles& shape : shapes) values.push_back(smallest_spacing(shape));
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
  }

  static void expect_on_surface(const std::vector<ShapeParticles>& shapes) {
    for (const ShapeParticles& shape : shapes) {
      ASSERT_EQ(shape.at.size(), kTransferredParticles);
      for (const SurfaceLocation& at : shape.at) {
        ASSERT_LT(at.triangle, shape.mesh->triangles().size());
        const Triangle& t = shape.mesh->triangles()[at.triangle];
        Vec3 p{};
        for (std::size_t k = 0; k < 3; ++k) {
          EXPECT_GE(at.weights[k], -1e-12);
          p = p + at.weights[k] * shape.mesh->positions()[t[k]];
        }
        EXPECT_NEAR(at.weights[0] + at.weights[1] + at.weights[2], 1.0, 1e-9);
        EXPECT_LT(norm(p + (-1.0) * at.at), 1e-9);
      }
    }
  }

  static bool same_places(const std::vector<ShapeParticles>& a, const std::vector<ShapeParticles>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) {
      for (std::size_t i = 0; i < kTransferredParticles; ++i) {
        const SurfaceLocation &p = a[k].at[i], &q = b[k].at[i];
        if (p.triangle != q.triangle || p.weights != q.weights || p.at.x != q.at.x || p.at.y != q.at.y || p.at.z != q.at.z) {
          return false;
        }
      }
    }
    return true;
  }

  std::vector<SurfaceMesh> meshes_;
  std::vector<ShapeParticles> start_;
};

TEST_F(JointRefinement, IterationsEvenTheShapesOutOnTheirSurfaces) {
  JointRefinementOptions options;
  options.iterations = 20;
  JointRefinementRecord record;
  const std::vector<ShapeParticles> shapes = iterated(options, 1, record);
  ASSERT_EQ(record.overlap.size(), 20u);
  ASSERT_EQ(record.correspondence_step.size(), 20u);
  EXPECT_LT(record.overlap.back(), 0.5 * record.overlap.front());
  EXPECT_GT(record.correspondence_step.front(), 0.0);
  expect_on_surface(shapes);
  EXPECT_GT(median_smallest_spacing(shapes), 1.5 * median_smallest_spacing(start_));
  // No iterations: nothing moves.
  options.iterations = 0;
  JointRefinementRecord none;
  EXPECT_TRUE(same_places(iterated(options, 1, none), start_));
  EXPECT_TRUE(none.overlap.empty());
}

TEST_F(JointRefinement, TheSameToTheBitWhateverTheThreads) {
  JointRefinementOptions options;
  options.iterations = 10;
  JointRefinementRecord one, two;
  const std::vector<ShapeParticles> a = iterated(options, 1, one), b = iterated(options, 2, two);
  EXPECT_TRUE(same_places(a, b));
  EXPECT_EQ(one.overlap, two.overlap);
  EXPECT_EQ(one.correspondence_step, two.correspondence_step);
}

// The packing's rounds are recorded; it is kept only where it leaves the
// shapes at least as spread as the iterations did, else undone.
TEST_F(JointRefinement, ThePackingIsKeptOnlyWhereItSpreadsTheShapes) {
  JointRefinementOptions options;
  options.iterations = 10;
  JointRefinementRecord record;
  std::vector<ShapeParticles> shapes = iterated(options, 2, record);
  const std::vector<ShapeParticles> before = shapes;
  ShapeShare share(shapes.size(), 2);
  pack_jointly(shapes, kTransferredParticles, options, share, record, true);
  EXPECT_GT(record.packing_rounds, 0u);
  EXPECT_EQ(record.packing_spacing.size(), record.packing_rounds);
  EXPECT_EQ(record.packing_correspondence_step.size(), record.packing_rounds);
  expect_on_surface(shapes);
  if (record.packing_undone) {
    EXPECT_TRUE(same_places(shapes, before));
  } else {
    EXPECT_GE(median_smallest_spacing(shapes), median_smallest_spacing(before));
  }
  // Without --packing: nothing moves.
  options.pack = false;
  std::vector<ShapeParticles> unpacked = before;
  JointRefinementRecord unrecorded;
  pack_jointly(unpacked, kTransferredParticles, options, share, unrecorded, true);
  EXPECT_TRUE(same_places(unpacked, before));
  EXPECT_EQ(unrecorded.packing_rounds, 0u);
}

// Each shape keeps a share of its evening (in tenths) from its transfer's
// places (here, the places after 20 iterations) to the refinement's (after
// 20 more); the shapes it holds back keep their closest pair `even_enough`
// spacings apart. Where the transfer's places are the refinement's, nothing moves.
TEST_F(JointRefinement, TheHoldBackKeepsAShareOfEachShapesEvening) {
  JointRefinementOptions options;
  options.iterations = 20;
  options.even_enough = 0.3;
  JointRefinementRecord record;
  std::vector<ShapeParticles> shapes = held_back(options, record).shapes;
  ShapeShare share(shapes.size(), 2);
  ASSERT_EQ(record.evening_kept.size(), 3u);
  expect_on_surface(shapes);
  std::size_t held_back = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double kept = record.evening_kept[k];
    EXPECT_GE(kept, 0.0);
    EXPECT_LE(kept, 1.0);
    EXPECT_NEAR(kept * 10, std::round(kept * 10), 1e-12) << "tenths";
    if (kept < 1) {
      ++held_back;
      EXPECT_GE(smallest_spacing(shapes[k]), options.even_enough) << "shape " << k;
    }
  }
  EXPECT_GT(held_back, 0u);

  const std::vector<ShapeParticles> refined = shapes;
  std::vector<std::vector<SurfaceLocation>> same;
  for (const ShapeParticles& shape : refined) same.push_back(shape.at);
  hold_back_evening(shapes, same, kTransferredParticles, kNoHoleLimit, options, share, record);
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t i = 0; i < kTransferredParticles; ++i) {
      EXPECT_LT(norm(shapes[k].at[i].at + (-1.0) * refined[k].at[i].at), 1e-12) << "shape " << k << " particle " << i;
    }
  }
}

// Where no share of the evening is even enough (here: the closest pair a
// whole hexagonal spacing apart, which 40 particles crowded at a pole after
// a few iterations are not), each shape takes sweeps that only widen gaps:
// they run, and no shape's closest pair ends closer than it was.
TEST_F(JointRefinement, AShapeStillUnderEvenEnoughTakesSweepsThatOnlyWiden) {
  JointRefinementOptions options;
  options.iterations = 5;
  options.even_enough = 1.0;
  JointRefinementRecord record;
  const auto [refined, shapes] = held_back(options, record);
  ASSERT_EQ(record.gap_sweeps.size(), 3u);
  ASSERT_EQ(record.hole_swaps.size(), 3u);
  expect_on_surface(shapes);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(record.evening_kept[k], 1.0) << "shape " << k;
    EXPECT_GT(record.gap_sweeps[k], 0u) << "shape " << k;
    EXPECT_GE(smallest_spacing(shapes[k]), smallest_spacing(refined[k])) << "shape " << k;
  }
  EXPECT_FALSE(same_places(shapes, refined));
}

}  // namespace
}  // namespace meshparticles::testing
