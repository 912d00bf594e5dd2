#pragma once
// Files ParaView (and most viewers) open directly: the particles as a PLY
// point cloud, and the mesh with one value per vertex as a VTK legacy
// polydata file (ASCII) and as VTK XML PolyData (.vtp, base64 binary, for
// VTK pipelines and ParaView). Written atomically; coordinates exact (every
// double as it is: common/exact_number.hpp, and Float64 in the .vtp).
#include <filesystem>
#include <span>
#include <string>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// One vertex element per particle: its point, index and nearest input vertex (file id).
void write_particles_ply(const std::filesystem::path& file, std::span<const Vec3> points,
                         std::span<const VertexId> input_vertices);

// The mesh's triangles with `values[v]` at each vertex, named `name`
// (infinite values, e.g. a component without particles, are written as -1).
void write_mesh_field_vtk(const std::filesystem::path& file, const SurfaceMesh& mesh, std::span<const float> values,
                          const std::string& name);

// The same as XML PolyData: Float64 points, Float32 values, Int64 connectivity,
// each array one base64 block with a UInt64 byte count, little-endian.
void write_mesh_field_vtp(const std::filesystem::path& file, const SurfaceMesh& mesh, std::span<const float> values,
                          const std::string& name);

}  // namespace meshparticles
