// Every kernel, at every work-group and tile size in kernel_sizes(), against
// the serial reference on random configurations: each particle must choose a
// candidate whose energy (recomputed in double) is within 1e-5 relative of
// the reference's, and exactly the reference's choice where that is unique by
// more than the tolerance. Meshes: irregular valence (torus), a boundary
// (patch), two components, valence 24.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/random.hpp"
#include "common/user_error.hpp"
#include "particle_test_support.hpp"
#include "particles/energy.hpp"

namespace meshparticles::testing {
namespace {

constexpr double kTolerance = 1e-5;

// Random vertices, a few of them shared by several particles so that stack
// ranks above zero are exercised too.
std::vector<VertexId> random_configuration(std::size_t vertex_count, std::size_t particles, std::uint64_t seed) {
  SplitMix64 random(seed);
  std::vector<VertexId> positions(particles);
  for (auto& p : positions) p = VertexId(random.below(vertex_count));
  for (std::size_t k = 0; k < particles / 10; ++k) positions[random.below(particles)] = positions[random.below(particles)];
  return positions;
}

// The candidate indices of one particle in rank order.
std::vector<std::size_t> ranked(const std::vector<double>& energies) {
  std::vector<std::size_t> order(energies.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return ranks_before(energies[a], a, energies[b], b); });
  return order;
}

class KernelAgreement : public ::testing::TestWithParam<const char*> {};

TEST_P(KernelAgreement, EveryKernelSizeChoosesTheReferenceMinimum) {
  const MeshWithDistances m(GetParam());
  const std::size_t vertex_count = m.mesh.vertex_count();
  const std::size_t particles = std::min<std::size_t>(150, std::max<std::size_t>(2, vertex_count / 2));
  const EnergyParams energy = m.default_energy(particles);
  SerialBackend reference(m.mesh, m.distances, energy);

  for (const auto& size : kernel_sizes()) {
    SCOPED_TRACE(describe(size));
    auto kernel = device_backend(m, energy, size.kind, size.work_group, size.tile);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const std::vector<VertexId> start = random_configuration(vertex_count, particles, seed);
      kernel->set_positions(start);
      kernel->iterate(Scheme::synchronous, 1);
      const std::vector<VertexId> chosen = kernel->last_choices();
      std::size_t exact_checks = 0, ranked_choices = 0;
      for (std::size_t c = 0; c < particles; ++c) {
        const VertexId here = start[c];
        std::size_t stack_rank = 0;
        for (std::size_t i = 0; i < c; ++i) stack_rank += start[i] == here;
        const std::vector<double> energies = reference.candidate_energies(c, start);
        const std::vector<std::size_t> order = ranked(energies);
        if (stack_rank >= energies.size() || std::isinf(energies[order[stack_rank]])) {
          EXPECT_EQ(chosen[c], here) << "particle " << c << " has no free candidate of rank " << stack_rank;
          continue;
        }
        const auto ring = m.mesh.one_ring(here);
        const auto index_of = [&](VertexId v) -> std::size_t {
          if (v == here) return 0;
          const auto it = std::find(ring.begin(), ring.end(), v);
          return it == ring.end() ? energies.size() : std::size_t(it - ring.begin()) + 1;
        };
        const std::size_t got = index_of(chosen[c]);
        ASSERT_LT(got, energies.size()) << "particle " << c << " jumped to a vertex that is not a candidate";
        const double want = energies[order[stack_rank]];
        const double scale = std::max(std::abs(want), 1e-30);
        EXPECT_LE(std::abs(energies[got] - want), kTolerance * scale) << "particle " << c << " seed " << seed;
        bool unique = true;
        for (std::size_t j = 0; j < energies.size(); ++j) {
          if (j != order[stack_rank] && std::abs(energies[j] - want) <= kTolerance * scale) unique = false;
        }
        ++ranked_choices;
        if (unique) {
          ++exact_checks;
          EXPECT_EQ(got, order[stack_rank]) << "particle " << c << " seed " << seed;
        }
      }
      // The tiny meshes are symmetric: there, ties are the point.
      if (vertex_count >= 100) EXPECT_GT(2 * exact_checks, ranked_choices) << "too many near-ties to mean much";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, KernelAgreement,
                         ::testing::Values("torus.off", "patch.off", "two_pieces.off", "high_valence.off"),
                         [](const auto& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(DeviceEnergy, TotalEnergyMatchesTheReference) {
  const MeshWithDistances m("torus.off");
  const EnergyParams energy = m.default_energy(300);
  const auto start = random_configuration(m.mesh.vertex_count(), 300, 7);
  SerialBackend reference(m.mesh, m.distances, energy);
  reference.set_positions(start);
  for (const auto kind : {KernelKind::naive, KernelKind::tiled}) {
    auto kernel = device_backend(m, energy, kind, 16, 64);
    kernel->set_positions(start);
    EXPECT_NEAR(kernel->total_energy(), reference.total_energy(), 1e-5 * reference.total_energy());
  }
}

TEST(DeviceLimits, RefusedSizesNameTheLimit) {
  const MeshWithDistances m("tetrahedron.off");
  const EnergyParams energy = m.default_energy(2);
  const DeviceDescription device = select_device("");
  try {
    device_backend(m, energy, KernelKind::tiled, device.max_work_group_size + 1, 16);
    FAIL() << "an oversized work-group was accepted";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("maximum work-group size " + std::to_string(device.max_work_group_size)),
              std::string::npos)
        << error.what();
  }
  try {
    device_backend(m, energy, KernelKind::tiled, 8, device.local_memory_bytes);
    FAIL() << "a tile larger than local memory was accepted";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("bytes of local memory"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace meshparticles::testing
