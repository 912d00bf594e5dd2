// Every kernel, at every work-group and tile size in kernel_sizes(), against
// the serial reference on random configurations: each particle must choose a
// candidate whose energy (recomputed in double) is within 1e-5 relative of
// the reference's, and exactly the reference's choice where that is unique by
// more than the tolerance. Meshes: irregular valence (torus), a boundary
// (patch), two components, valence 24; both potentials.
#include <gtest/gtest.h>

#include <algorithm>

#include "backends/reference_check.hpp"
#include "common/random.hpp"
#include "common/user_error.hpp"
#include "particle_test_support.hpp"

namespace meshparticles::testing {
namespace {

// Random vertices, a few of them shared by several particles so that stack
// ranks above zero are exercised too.
std::vector<VertexId> random_configuration(std::size_t vertex_count, std::size_t particles, std::uint64_t seed) {
  SplitMix64 random(seed);
  std::vector<VertexId> positions(particles);
  for (auto& p : positions) p = VertexId(random.below(vertex_count));
  for (std::size_t k = 0; k < particles / 10; ++k) positions[random.below(particles)] = positions[random.below(particles)];
  return positions;
}

struct AgreementCase {
  const char* mesh;
  Potential potential;
};

class KernelAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(KernelAgreement, EveryKernelSizeChoosesTheReferenceMinimum) {
  const MeshWithDistances m(GetParam().mesh);
  const std::size_t vertex_count = m.mesh.vertex_count();
  const std::size_t particles = std::min<std::size_t>(150, std::max<std::size_t>(2, vertex_count / 2));
  const EnergyParams energy = m.default_energy(particles, GetParam().potential);
  SerialBackend reference(m.mesh, m.distances, energy);

  for (const auto& size : kernel_sizes()) {
    SCOPED_TRACE(describe(size));
    auto kernel = device_backend(m, energy, size.kind, size.work_group, size.tile);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const std::vector<VertexId> start = random_configuration(vertex_count, particles, seed);
      kernel->set_positions(start);
      const ChoiceVerdict verdict = ReferenceChoices(m.mesh, reference, start).check(kernel->synchronous_choices());
      EXPECT_EQ(verdict.wrong, 0u) << "seed " << seed << ": " << verdict.first_wrong;
      // The tiny meshes are symmetric: there, ties are the point.
      if (vertex_count >= 100) {
        EXPECT_GT(2 * verdict.exact_checks, verdict.ranked_choices) << "too many near-ties to mean much";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, KernelAgreement,
                         ::testing::Values(AgreementCase{"torus.off", Potential::exp},
                                           AgreementCase{"patch.off", Potential::exp},
                                           AgreementCase{"two_pieces.off", Potential::exp},
                                           AgreementCase{"high_valence.off", Potential::exp},
                                           AgreementCase{"torus.off", Potential::gauss},
                                           AgreementCase{"high_valence.off", Potential::gauss}),
                         [](const auto& param_info) {
                           return mesh_stem(param_info.param.mesh) + "_" + potential_name(param_info.param.potential);
                         });

// What the sweep relies on: measuring moves nothing, and the choices it
// verifies are those a synchronous iteration commits from.
TEST(DeviceMeasurement, TimingAndChoicesLeaveThePositionsAlone) {
  const MeshWithDistances m("torus.off");
  const EnergyParams energy = m.default_energy(200);
  const auto start = random_configuration(m.mesh.vertex_count(), 200, 5);
  for (const std::string kind : {"naive", "tiled", "field"}) {
    auto kernel = device_backend(m, energy, kind, 16, kind == "tiled" ? 64 : 0);
    kernel->set_positions(start);
    const std::vector<VertexId> choices = kernel->synchronous_choices();
    EXPECT_GT(kernel->time_update_kernels(Scheme::colored, 16), 0.0);
    EXPECT_GT(kernel->time_update_kernels(Scheme::synchronous, 1), 0.0);
    EXPECT_EQ(kernel->positions(), start);
    EXPECT_NE(choices, start) << "a random start should give some moves";
    kernel->iterate(Scheme::synchronous, 1);
    EXPECT_EQ(kernel->last_choices(), choices);
  }
}

TEST(DeviceEnergy, TotalEnergyMatchesTheReference) {
  const MeshWithDistances m("torus.off");
  const EnergyParams energy = m.default_energy(300);
  const auto start = random_configuration(m.mesh.vertex_count(), 300, 7);
  SerialBackend reference(m.mesh, m.distances, energy);
  reference.set_positions(start);
  for (const std::string kind : {"naive", "tiled", "field"}) {
    auto kernel = device_backend(m, energy, kind, 16, kind == "tiled" ? 64 : 0);
    kernel->set_positions(start);
    EXPECT_NEAR(kernel->total_energy(), reference.total_energy(), 1e-5 * reference.total_energy());
  }
}

TEST(DeviceLimits, RefusedSizesNameTheLimit) {
  const MeshWithDistances m("tetrahedron.off");
  const EnergyParams energy = m.default_energy(2);
  const DeviceDescription device = select_device("");
  try {
    device_backend(m, energy, "tiled", device.max_work_group_size + 1, 16);
    FAIL() << "an oversized work-group was accepted";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("maximum work-group size " + std::to_string(device.max_work_group_size)),
              std::string::npos)
        << error.what();
  }
  try {
    device_backend(m, energy, "tiled", 8, device.local_memory_bytes);
    FAIL() << "a tile larger than local memory was accepted";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("bytes of local memory"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace meshparticles::testing
