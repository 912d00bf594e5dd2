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
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// Creates `directory` if needed; throws UserError when it cannot be written.
void prepare_output_directory(const std::filesystem::path& directory);

// Every file of the result, report.json last.
void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh, const RunResult& result,
                       const nlohmann::json& report);

}  // namespace meshparticles
