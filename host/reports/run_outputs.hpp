#pragma once
// What `meshparticles run` leaves in its output directory, each file written
// atomically: particles.particles (ShapeWorks: one "x y z" per line),
// particles.csv (particle,vertex,x,y,z with input vertex ids), report.json
// (mesh, parameters, device, trace, timings, quality), and for ParaView
// particles.ply (point cloud) and mesh_distance.vtk (the mesh with the
// distance from each vertex to its nearest particle).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "mesh/surface_mesh.hpp"
#include "particles/particle_run.hpp"

namespace meshparticles {

struct RunContext {
  std::string mesh_path;
  nlohmann::json params;  // every option in effect
  std::string device;     // "serial" or the OpenCL device name
};

nlohmann::json run_report(const SurfaceMesh& mesh, const RunContext& context, const RunOutcome& outcome);

// Creates `directory` if needed; throws UserError when it cannot be written.
void prepare_output_directory(const std::filesystem::path& directory);

void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh,
                       const std::vector<VertexId>& positions, const nlohmann::json& report,
                       std::span<const float> distance_to_nearest_particle);

}  // namespace meshparticles
