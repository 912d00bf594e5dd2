#pragma once
// A strip folded back on itself (or twice, as a Z), its sheets a twentieth
// of a spacing apart through the air and far apart along the surface: where
// straight lines misjudge the surface. Shared by the tests of what must
// follow the surface (the evening step, surface neighbours, the hole pull).
#include <cmath>
#include <numbers>
#include <vector>

#include "common/random.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles::testing {

inline constexpr double kLength = 4, kWidth = 2, kBend = 0.025;  // the fold's radius: the sheets are 0.05 apart

// A strip kLength long on each side, folded back around a half cylinder of
// radius kBend: (x, z) along its middle line at arc length u.
inline Vec3 on_fold(double u, double y) {
  const double around = std::numbers::pi * kBend;
  if (u <= kLength) return {u, y, 0};
  if (u < kLength + around) {
    const double angle = (u - kLength) / kBend - std::numbers::pi / 2;
    return {kLength + kBend * std::cos(angle), y, kBend + kBend * std::sin(angle)};
  }
  return {kLength - (u - kLength - around), y, 2 * kBend};
}

// A strip folded twice, as a Z: three sheets kBend * 2 apart, the first and
// the third facing the same way (their normals agree, so straight lines
// between them count as facing pairs).
inline Vec3 on_z_fold(double u, double y) {
  const double around = std::numbers::pi * kBend;
  if (u <= kLength) return {u, y, 0};
  u -= kLength;
  if (u < around) return {kLength + kBend * std::sin(u / kBend), y, kBend - kBend * std::cos(u / kBend)};
  u -= around;
  if (u <= kLength) return {kLength - u, y, 2 * kBend};
  u -= kLength;
  if (u < around) return {-kBend * std::sin(u / kBend), y, 3 * kBend - kBend * std::cos(u / kBend)};
  return {u - around, y, 4 * kBend};
}

inline SurfaceMesh folded_strip(int folds = 1) {
  const int kAlong = 160 * folds, kAcross = 16;
  const double total = (folds + 1) * kLength + folds * std::numbers::pi * kBend;
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  // Vertices off the grid (by up to a third of a cell along the strip and
  // across it), so that no lattice of particles fits them.
  SplitMix64 random(5);
  const auto jitter = [&](int k, int last) { return k == 0 || k == last ? 0.0 : (random.uniform() - 0.5) * 0.66; };
  for (int i = 0; i <= kAlong; ++i) {
    for (int j = 0; j <= kAcross; ++j) {
      const double u = total * (i + jitter(i, kAlong)) / kAlong, y = kWidth * (j + jitter(j, kAcross)) / kAcross;
      positions.push_back(folds == 1 ? on_fold(u, y) : on_z_fold(u, y));
    }
  }
  const auto at = [](int i, int j) { return VertexId(i * (kAcross + 1) + j); };
  for (int i = 0; i < kAlong; ++i) {
    for (int j = 0; j < kAcross; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return SurfaceMesh(positions, triangles);
}

}  // namespace meshparticles::testing
