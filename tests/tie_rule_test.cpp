// The tie rule, exactly: among candidates of equal energy the smaller index
// wins (the vertex itself first, then its one-ring by increasing id). A
// hand-made problem where four candidates tie exactly in every precision:
// particle 0 at the centre of a hexagon fan, particles 1 and 2 at opposite
// corners, and distances counted in steps (centre to corner 1, corner to
// corner around the ring). Corners 2, 3, 5 and 6 all have energy
// w(1) + w(2), below staying (2 w(1)): every backend must take corner 2.
#include <gtest/gtest.h>

#include "backends/backend_factory.hpp"
#include "backends/backend_table.hpp"
#include "geodesics/distance_table.hpp"

namespace meshparticles::testing {
namespace {

SurfaceMesh hexagon_fan() {
  std::vector<Vec3> positions = {{0, 0, 0}};
  std::vector<Triangle> triangles;
  for (int k = 0; k < 6; ++k) {
    positions.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0});
    triangles.push_back({0, VertexId(1 + k), VertexId(1 + (k + 1) % 6)});
  }
  return SurfaceMesh(positions, triangles);
}

DistanceTable ring_steps(const SurfaceMesh& mesh) {
  DistanceTable table(mesh.vertex_count());
  for (VertexId a = 0; a < 7; ++a) {
    for (VertexId b = 0; b < 7; ++b) {
      const int around = std::abs(int(a) - int(b));
      table.row(a)[b] = a == b ? 0.0f : (a == 0 || b == 0) ? 1.0f : float(std::min(around, 6 - around));
    }
  }
  return table;
}

TEST(TieRule, EqualEnergiesGoToTheSmallerIndexOnEveryBackend) {
  const SurfaceMesh mesh = hexagon_fan();
  const DistanceTable distances = ring_steps(mesh);
  for (const Potential potential : {Potential::exp, Potential::gauss}) {
    const EnergyParams energy{potential, 1.0};
    for (const std::string& name : backend_names()) {
      SCOPED_TRACE(name + " " + potential_name(potential));
      BackendRequest request;
      request.name = name;
      const auto backend = make_backend(check_backend(request, mesh, 3), mesh, distances, energy);
      backend->set_positions(std::vector<VertexId>{0, 1, 4});
      backend->iterate(Scheme::colored, 3);  // particle 0 alone in its colour, first
      EXPECT_EQ(backend->positions()[0], 2u) << "of corners 2, 3, 5 and 6, tied, the smallest id";
    }
  }
}

// Staying ties with moving: a particle moves only to a strictly lower energy.
TEST(TieRule, AParticleStaysWhenNoCandidateIsStrictlyBetter) {
  const SurfaceMesh mesh = hexagon_fan();
  DistanceTable distances = ring_steps(mesh);
  // Corners at distance 1 from the centre and from each other: from corner
  // 1 (particle 0), with particle 1 at corner 4, staying costs w(3) and so
  // does... nothing: make corners 2 and 6 as far from corner 4 as corner 1 is.
  for (const VertexId corner : {VertexId(2), VertexId(6)}) {
    distances.row(corner)[4] = distances.row(4)[corner] = 3.0f;
  }
  const EnergyParams energy{Potential::exp, 1.0};
  for (const std::string& name : backend_names()) {
    SCOPED_TRACE(name);
    BackendRequest request;
    request.name = name;
    const auto backend = make_backend(check_backend(request, mesh, 2), mesh, distances, energy);
    backend->set_positions(std::vector<VertexId>{1, 4});
    backend->iterate(Scheme::colored, 2);
    EXPECT_EQ(backend->positions()[0], 1u) << "candidates 2 and 6 only tie with staying";
  }
}

}  // namespace
}  // namespace meshparticles::testing
