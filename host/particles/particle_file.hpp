#pragma once
// Particle sets from files, for `quality` and `compare`: the ShapeWorks
// `.particles` format that `run` also writes (one "x y z" per line, no
// header), snapped to the mesh's nearest vertices.
#include <filesystem>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Throws UserError naming the file (and the line) for a missing or empty
// file, a line that is not three finite numbers.
// Coordinates larger than this are refused: their squares, summed over a
// shape, would overflow a double (the shape model's Procrustes and modes).
inline constexpr double kLargestParticleCoordinate = 1e150;

std::vector<Vec3> read_particle_points(const std::filesystem::path& file);

struct SnappedParticles {
  std::vector<VertexId> positions;  // the nearest vertex of each point
  double largest_snap = 0;          // the largest point-to-vertex distance, mesh units
  std::size_t largest_snap_particle = 0;
};

// Each point to its nearest vertex (Euclidean; ties to the smaller id).
SnappedParticles snap_to_vertices(const SurfaceMesh& mesh, const std::vector<Vec3>& points);

}  // namespace meshparticles
