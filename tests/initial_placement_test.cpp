// Starting configurations: seeded, distinct where promised, and farthest
// point sampling visits every component before doubling up.
#include <gtest/gtest.h>

#include <optional>
#include <set>

#include "particle_test_support.hpp"
#include "common/random.hpp"
#include "particles/farthest_vertex.hpp"
#include "particles/initial_placement.hpp"

namespace meshparticles::testing {
namespace {

std::size_t distinct(const std::vector<VertexId>& positions) {
  return std::set<VertexId>(positions.begin(), positions.end()).size();
}

TEST(InitialPlacement, RandomIsDistinctAndSeeded) {
  const MeshWithDistances m("patch.off");
  const auto a = place_particles(m.mesh, {Init::random, 400, 9, std::nullopt});
  EXPECT_EQ(distinct(a), 400u);  // every vertex, once
  const auto b = place_particles(m.mesh, {Init::random, 50, 9, std::nullopt});
  EXPECT_EQ(b, place_particles(m.mesh, {Init::random, 50, 9, std::nullopt}));
  EXPECT_NE(b, place_particles(m.mesh, {Init::random, 50, 10, std::nullopt}));
}

TEST(InitialPlacement, FarthestPointSamplingSpreadsAndCoversComponents) {
  const MeshWithDistances m("two_pieces.off");
  const auto two = place_particles(m.mesh, {Init::farthest, 2, 1, VertexId{0}});
  EXPECT_NE(m.mesh.component_of(two[0]), m.mesh.component_of(two[1]));
  EXPECT_EQ(distinct(place_particles(m.mesh, {Init::farthest, 8, 1, std::nullopt})), 8u);

  const MeshWithDistances patch("patch.off");
  const auto samples = place_particles(patch.mesh, {Init::farthest, 4, 1, VertexId{0}});
  // Each sample is at least as far from the earlier ones as any vertex is.
  for (std::size_t k = 1; k < samples.size(); ++k) {
    auto nearest = [&](VertexId v) {
      float d = INFINITY;
      for (std::size_t j = 0; j < k; ++j) d = std::min(d, patch.distances(samples[j], v));
      return d;
    };
    for (VertexId v = 0; v < patch.mesh.vertex_count(); ++v) EXPECT_LE(nearest(v), nearest(samples[k]));
  }
}

// The tree of block maxima answers what a scan of every vertex answers, as
// distances drop at random (ties on purpose: few distinct values) and
// vertices are taken, until none is left.
TEST(FarthestVertex, AnswersWhatAScanAnswers) {
  const std::size_t vertex_count = 1000;  // 16 blocks, the last one partial
  std::vector<float> nearest(vertex_count, INFINITY);
  FarthestVertex farthest(nearest);
  std::vector<bool> taken(vertex_count, false);
  SplitMix64 random(7);
  const auto scan = [&]() -> std::optional<VertexId> {
    std::optional<VertexId> best;
    for (VertexId v = 0; v < vertex_count; ++v) {
      if (!taken[v] && (!best || nearest[v] > nearest[*best])) best = v;  // the first of equals: the smaller id
    }
    return best;
  };
  for (std::size_t step = 0; step < vertex_count; ++step) {
    ASSERT_EQ(farthest.farthest(), scan()) << "step " << step;
    const VertexId next = *farthest.farthest();
    taken[next] = true;
    farthest.take(next);
    std::vector<VertexId> lowered;
    const VertexId around = VertexId(random.below(vertex_count));
    for (VertexId v = around; v < std::min<std::size_t>(vertex_count, around + 1 + random.below(90)); ++v) {
      const float lower = float(random.below(20));
      if (lower < nearest[v]) {
        nearest[v] = lower;
        lowered.push_back(v);
      }
    }
    farthest.lowered(lowered);
  }
  EXPECT_EQ(farthest.farthest(), std::nullopt);
}

TEST(InitialPlacement, PapersStartStacksEveryParticle) {
  const MeshWithDistances m("tetrahedron.off");
  EXPECT_EQ(place_particles(m.mesh, {Init::v0, 3, 0, VertexId{2}}), (std::vector<VertexId>{2, 2, 2}));
}

TEST(DefaultSigma, FollowsTheHexagonalSpacing) {
  const double d_hex = hexagonal_spacing(12.0, 100);
  EXPECT_NEAR(d_hex, std::sqrt(24.0 / (std::sqrt(3.0) * 100)), 1e-15);
  const double sigma = default_sigma(Potential::exp, 12.0, 100);
  EXPECT_NEAR(2 * sigma * sigma, d_hex / 2, 1e-15);
  EXPECT_NEAR(default_sigma(Potential::gauss, 12.0, 100), d_hex / 2, 1e-15);
}

}  // namespace
}  // namespace meshparticles::testing
