// Quality metrics on configurations whose answers are known by hand: a
// regular grid on the unit square (geodesics there are straight lines), two
// particles at a known distance, a stack, a component without particles; and
// the particle-file reader against bad files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <random>
#include <tuple>
#include <utility>

#include <unistd.h>

#include "common/user_error.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "particle_test_support.hpp"
#include "particles/particle_file.hpp"
#include "quality/distribution_quality.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles::testing {
namespace {

// An 11 x 11 grid of spacing 0.1 on the unit square, two triangles per cell.
class GridSquare : public ::testing::Test {
 protected:
  static constexpr int kSide = 11;
  static void SetUpTestSuite() {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "meshparticles_grid.off";
    {
      std::ofstream out(file);
      out << "OFF\n" << kSide * kSide << " " << 2 * (kSide - 1) * (kSide - 1) << " 0\n";
      for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) out << 0.1 * i << " " << 0.1 * j << " 0\n";
      }
      for (int j = 0; j + 1 < kSide; ++j) {
        for (int i = 0; i + 1 < kSide; ++i) {
          const int a = j * kSide + i, b = a + 1, c = a + kSide, d = c + 1;
          out << "3 " << a << " " << b << " " << d << "\n3 " << a << " " << d << " " << c << "\n";
        }
      }
    }
    std::vector<std::string> warnings;
    mesh_ = new SurfaceMesh(read_mesh(file, warnings));
    distances_ = new DistanceTable(compute_all_pairs(*mesh_, GeodesicMethod::fast_marching, 0, true));
  }
  static void TearDownTestSuite() {
    delete distances_;
    delete mesh_;
  }
  // The vertex at grid point (i, j): the reader keeps the file's order here.
  static VertexId at(int i, int j) {
    const VertexId v = VertexId(j * kSide + i);
    EXPECT_NEAR(mesh_->positions()[v].x, 0.1 * i, 1e-6);  // read as float
    return v;
  }
  static DistributionQuality measure(const std::vector<VertexId>& positions, double sigma = 0.1) {
    return measure_quality(*mesh_, *distances_, positions, {Potential::exp, sigma},
                           distance_to_nearest_particle(*mesh_, GeodesicMethod::fast_marching, positions), true);
  }
  static SurfaceMesh* mesh_;
  static DistanceTable* distances_;
};
SurfaceMesh* GridSquare::mesh_ = nullptr;
DistanceTable* GridSquare::distances_ = nullptr;

TEST_F(GridSquare, TwoParticlesAtAKnownDistance) {
  const double sigma = 0.2;
  const DistributionQuality q = measure({at(0, 0), at(5, 0)}, sigma);
  ASSERT_TRUE(q.nn_min && q.nn_mean && q.nn_cv && q.rho && q.cover);
  EXPECT_NEAR(*q.nn_min, 0.5, 1e-6);
  EXPECT_NEAR(*q.nn_mean, 0.5, 1e-6);
  EXPECT_NEAR(*q.nn_cv, 0.0, 1e-9);
  const double d_hex = std::sqrt(2.0 / (std::sqrt(3.0) * 2));
  EXPECT_NEAR(q.d_hex, d_hex, 1e-9);
  EXPECT_NEAR(*q.rho, 0.5 / d_hex, 1e-5);
  EXPECT_NEAR(q.energy, std::exp(-0.5 / (2 * sigma * sigma)), 1e-6);
  // The farthest vertex from both is the corner (1, 1), sqrt(0.5^2 + 1) from (0.5, 0).
  EXPECT_NEAR(*q.cover * d_hex, std::sqrt(1.25), 1e-3);
  EXPECT_EQ(q.stacked, 0u);
}

TEST_F(GridSquare, ARegularLatticeHasNoSpreadInItsSpacing) {
  std::vector<VertexId> lattice;  // every other grid point: spacing 0.2, 36 particles
  for (int j = 0; j < kSide; j += 2) {
    for (int i = 0; i < kSide; i += 2) lattice.push_back(at(i, j));
  }
  const DistributionQuality q = measure(lattice);
  ASSERT_TRUE(q.nn_min && q.nn_mean && q.nn_cv && q.rho && q.cover);
  EXPECT_NEAR(*q.nn_min, 0.2, 1e-6);
  EXPECT_NEAR(*q.nn_mean, 0.2, 1e-6);
  EXPECT_NEAR(*q.nn_cv, 0.0, 1e-5);
  const double d_hex = std::sqrt(2.0 / (std::sqrt(3.0) * 36));
  EXPECT_NEAR(*q.rho, 0.2 / d_hex, 1e-5);
  // The cell centres (odd, odd) are farthest from every particle: a half diagonal.
  EXPECT_NEAR(*q.cover * d_hex, std::sqrt(0.02), 1e-3);
  double energy = 0;  // straight-line distances on the flat square
  for (std::size_t a = 0; a < lattice.size(); ++a) {
    for (std::size_t b = a + 1; b < lattice.size(); ++b) {
      const Vec3 d = mesh_->positions()[lattice[a]] - mesh_->positions()[lattice[b]];
      energy += std::exp(-std::sqrt(dot(d, d)) / (2 * 0.1 * 0.1));
    }
  }
  EXPECT_NEAR(q.energy, energy, 1e-4 * energy);
  EXPECT_EQ(q.stacked, 0u);

  double partner_energy = 1.0;  // a second particle on lattice[7]: w(0) with it, and its pairs with the rest
  for (std::size_t b = 0; b < lattice.size(); ++b) {
    if (b != 7) partner_energy += std::exp(-(*distances_)(lattice[7], lattice[b]) / (2 * 0.1 * 0.1));
  }
  lattice.push_back(lattice[7]);
  const DistributionQuality stacked = measure(lattice);
  EXPECT_EQ(stacked.stacked, 1u);
  EXPECT_EQ(*stacked.nn_min, 0.0);
  EXPECT_EQ(*stacked.rho, 0.0);
  EXPECT_NEAR(stacked.energy, q.energy + partner_energy, 1e-9 * stacked.energy);
}

TEST(Quality, AComponentWithoutParticlesLeavesTheCoverUndefined) {
  const MeshWithDistances m("two_pieces.off");
  ASSERT_EQ(m.mesh.component_count(), 2u);
  std::vector<VertexId> one_side, both_sides;
  for (VertexId v = 0; v < m.mesh.vertex_count(); ++v) {
    if (m.mesh.component_of(v) == m.mesh.component_of(0) && one_side.size() < 2) one_side.push_back(v);
    if (m.mesh.component_of(v) != m.mesh.component_of(0) && both_sides.empty()) both_sides.push_back(v);
  }
  both_sides.push_back(0);
  const EnergyParams energy{Potential::exp, 1.0};
  const auto measure = [&](const std::vector<VertexId>& positions) {
    return measure_quality(m.mesh, m.distances, positions, energy,
                           distance_to_nearest_particle(m.mesh, GeodesicMethod::fast_marching, positions), true);
  };
  const DistributionQuality one = measure(one_side);
  EXPECT_FALSE(one.cover.has_value());
  EXPECT_TRUE(one.nn_min.has_value());
  // One particle in each component: neither has a neighbour, both cover their own.
  const DistributionQuality two = measure(both_sides);
  EXPECT_FALSE(two.nn_min.has_value());
  EXPECT_EQ(two.alone, 2u);
  EXPECT_TRUE(two.cover.has_value());
  EXPECT_EQ(two.energy, 0.0);
  EXPECT_TRUE(quality_json(two)["nn_min"].is_null());
}

// A closed tube 10 long and 0.001 wide, 8 sides, rings every 0.05, capped.
SurfaceMesh thin_tube() {
  constexpr int kSides = 8, kRings = 201;
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (int k = 0; k < kRings; ++k) {
    for (int s = 0; s < kSides; ++s) {
      const double angle = 2 * M_PI * s / kSides;
      positions.push_back({0.05 * k, 0.0005 * std::cos(angle), 0.0005 * std::sin(angle)});
    }
  }
  const auto at = [](int k, int s) { return VertexId(k * kSides + (s % kSides)); };
  for (int k = 0; k + 1 < kRings; ++k) {
    for (int s = 0; s < kSides; ++s) {
      triangles.push_back({at(k, s), at(k, s + 1), at(k + 1, s + 1)});
      triangles.push_back({at(k, s), at(k + 1, s + 1), at(k + 1, s)});
    }
  }
  positions.push_back({0, 0, 0});
  positions.push_back({10, 0, 0});
  for (int s = 0; s < kSides; ++s) {
    triangles.push_back({VertexId(positions.size() - 2), at(0, s + 1), at(0, s)});
    triangles.push_back({VertexId(positions.size() - 1), at(kRings - 1, s), at(kRings - 1, s + 1)});
  }
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

// 20 particles along a thin tube lie 0.5 apart, where a local store's balls
// of 3 d_hex reach 0.13: each particle finds its nearest by a ball of its own
// (every one was reported alone, with no nn figures and energy 0), and the
// figures are the complete table's.
TEST(Quality, ParticlesAlongAThinTubeFindTheirNeighboursBeyondTheBalls) {
  const SurfaceMesh tube = thin_tube();
  std::vector<VertexId> positions;
  for (int k = 0; k < 20; ++k) positions.push_back(VertexId((5 + 10 * k) * 8 + k % 8));
  const double d_hex = hexagonal_spacing(tube.area(), positions.size());
  ASSERT_LT(3 * d_hex, 0.2);
  // Gaussian and narrow: pairs beyond the nearest weigh nothing next to them.
  const EnergyParams energy{Potential::gauss, 0.15};
  const std::vector<float> to_nearest = distance_to_nearest_particle(tube, GeodesicMethod::fast_marching, positions);
  const DistanceTable table = compute_all_pairs(tube, GeodesicMethod::fast_marching, 0, true);
  const DistributionQuality all = measure_quality(tube, table, positions, energy, to_nearest, true);
  const LocalDistances balls = local_store(tube, 3 * d_hex);
  const DistributionQuality local = measure_quality(tube, balls, positions, energy, to_nearest, true);
  ASSERT_EQ(all.alone, 0u);
  EXPECT_EQ(local.alone, 0u);
  ASSERT_TRUE(local.nn_min && local.nn_mean && local.nn_cv && local.rho);
  EXPECT_NEAR(*all.nn_min, 0.5, 0.01);
  EXPECT_NEAR(*local.nn_min, *all.nn_min, 1e-4 * *all.nn_min);
  EXPECT_NEAR(*local.nn_mean, *all.nn_mean, 1e-4 * *all.nn_mean);
  EXPECT_NEAR(*local.nn_cv, *all.nn_cv, 1e-3);
  EXPECT_NEAR(*local.rho, *all.rho, 1e-4 * *all.rho);
  EXPECT_GT(local.energy, 0.0);
  EXPECT_NEAR(local.energy, all.energy, 1e-3 * all.energy);  // each pair once
  // One particle alone in a component of its own stays alone.
  const MeshWithDistances two("two_pieces.off");
  std::vector<VertexId> apart{0};
  for (VertexId v = 0; v < two.mesh.vertex_count() && apart.size() < 2; ++v) {
    if (two.mesh.component_of(v) != two.mesh.component_of(0)) apart.push_back(v);
  }
  const LocalDistances two_balls = local_store(two.mesh, 0.01);
  const DistributionQuality alone = measure_quality(
      two.mesh, two_balls, apart, energy, distance_to_nearest_particle(two.mesh, GeodesicMethod::fast_marching, apart),
      true);
  EXPECT_EQ(alone.alone, 2u);
  EXPECT_FALSE(alone.nn_min.has_value());
  EXPECT_EQ(alone.energy, 0.0);
}

std::string error_of(const std::string& name) {
  try {
    read_particle_points(std::string(TEST_DATA_DIR) + "/particles/" + name);
  } catch (const UserError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ParticleFile, BadFilesGiveAClearError) {
  EXPECT_NE(error_of("missing.particles").find("missing.particles: no such file"), std::string::npos);
  EXPECT_NE(error_of("empty.particles").find("empty.particles: no particles"), std::string::npos);
  EXPECT_NE(error_of("two_numbers.particles").find("line 2 is not three numbers"), std::string::npos);
  EXPECT_NE(error_of("four_numbers.particles").find("line 1 is not three numbers"), std::string::npos);
  EXPECT_NE(error_of("header.particles").find("line 1 is not three numbers"), std::string::npos);
  EXPECT_NE(error_of("nan.particles").find("line 2"), std::string::npos);
  EXPECT_NE(error_of("").find("is a directory"), std::string::npos);
}

TEST(ParticleFile, PointsSnapToTheNearestVertexAndTheLargestSnapIsReported) {
  const auto points = read_particle_points(std::string(TEST_DATA_DIR) + "/particles/blank_lines.particles");
  ASSERT_EQ(points.size(), 2u);
  const MeshWithDistances m("tetrahedron.off");
  std::vector<Vec3> shifted;
  for (VertexId v = 0; v < m.mesh.vertex_count(); ++v) shifted.push_back(m.mesh.positions()[v] + Vec3{0.01 * v, 0, 0});
  const SnappedParticles snapped = snap_to_vertices(m.mesh, shifted);
  for (VertexId v = 0; v < m.mesh.vertex_count(); ++v) EXPECT_EQ(snapped.positions[v], v);
  EXPECT_NEAR(snapped.largest_snap, 0.01 * double(m.mesh.vertex_count() - 1), 1e-12);
  EXPECT_EQ(snapped.largest_snap_particle, m.mesh.vertex_count() - 1);
}

// The nearest vertex by a scan of them all, ties to the smaller id: what
// snapping is defined to give.
std::pair<VertexId, double> nearest_by_scan(const SurfaceMesh& mesh, Vec3 point) {
  VertexId nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 offset = mesh.positions()[v] - point;
    const double d = dot(offset, offset);
    if (d < best) std::tie(nearest, best) = std::pair(v, d);
  }
  return {nearest, best};
}

void expect_the_scans_answers(const SurfaceMesh& mesh, const std::vector<Vec3>& points) {
  const SnappedParticles snapped = snap_to_vertices(mesh, points);
  ASSERT_EQ(snapped.positions.size(), points.size());
  double largest = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [nearest, best] = nearest_by_scan(mesh, points[i]);
    ASSERT_EQ(snapped.positions[i], nearest) << "point " << i;
    largest = std::max(largest, std::sqrt(best));
  }
  EXPECT_EQ(snapped.largest_snap, largest);
}

// A flat grid of side x side vertices at integer coordinates, numbered in a
// shuffled order, so that the points equally near to several vertices lie
// in different leaves of the k-d tree, in no order of their ids.
SurfaceMesh shuffled_grid(std::size_t side) {
  std::vector<std::size_t> id(side * side);
  std::iota(id.begin(), id.end(), 0);
  std::shuffle(id.begin(), id.end(), std::mt19937(3));
  std::vector<Vec3> at(id.size());
  for (std::size_t k = 0; k < id.size(); ++k) at[id[k]] = {double(k % side), double(k / side), 0};
  const auto path = std::filesystem::temp_directory_path() / ("mp_grid_" + std::to_string(::getpid()) + ".off");
  {
    std::ofstream out(path);
    out << "OFF\n" << at.size() << " " << 2 * (side - 1) * (side - 1) << " 0\n";
    for (const Vec3& p : at) out << p.x << " " << p.y << " 0\n";
    for (std::size_t y = 0; y + 1 < side; ++y) {
      for (std::size_t x = 0; x + 1 < side; ++x) {
        const std::size_t a = id[y * side + x], b = id[y * side + x + 1], c = id[(y + 1) * side + x + 1],
                          d = id[(y + 1) * side + x];
        out << "3 " << a << " " << b << " " << c << "\n3 " << a << " " << c << " " << d << "\n";
      }
    }
  }
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_mesh(path.string(), warnings);
  std::filesystem::remove(path);
  return mesh;
}

// Snapping through the k-d tree gives the scan's vertex for every point: on
// a grid, points equally near to 2 and 4 vertices (exact in binary) go to the
// smallest id; on the atrium, random points around it, points on its
// vertices, and a point so far out that squared distances overflow.
TEST(ParticleFile, SnappingGivesTheScansVertexTiesIncluded) {
  const SurfaceMesh grid = shuffled_grid(40);
  std::vector<Vec3> equally_near;
  for (double y = 0; y <= 39; y += 0.5) {
    for (double x = 0; x <= 39; x += 0.5) equally_near.push_back({x, y, 0.25});
  }
  expect_the_scans_answers(grid, equally_near);

  std::vector<std::string> warnings;
  const SurfaceMesh atrium = read_mesh(std::string(MESHES_DIR) + "/atrium.off", warnings);
  Vec3 low = atrium.positions()[0], high = low;
  for (const Vec3& p : atrium.positions()) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  std::vector<Vec3> points;
  for (int k = 0; k < 3000; ++k) {
    points.push_back({low.x + unit(random) * (high.x - low.x), low.y + unit(random) * (high.y - low.y),
                      low.z + unit(random) * (high.z - low.z)});
  }
  for (VertexId v = 0; v < atrium.vertex_count(); v += 7) points.push_back(atrium.positions()[v]);
  points.push_back({1e200, -1e200, 1e200});  // every squared distance is +inf: the scan keeps vertex 0
  expect_the_scans_answers(atrium, points);
}

}  // namespace
}  // namespace meshparticles::testing
