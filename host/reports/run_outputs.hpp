#pragma once
// What `meshparticles run` leaves in its output directory, written as one
// set (common/atomic_directory.hpp: the old set or the new one, never a
// mix): particles.particles (ShapeWorks: one "x y z" per line),
// particles.csv (kParticlesCsvHeader: the nearest input vertex, the point,
// and a triangle of the input with barycentric weights; ids as in the
// file), report.json (mesh, parameters, device, trace, timings, quality,
// and the size and SHA-256 of each other file: reports/output_digests.hpp),
// and for ParaView particles.ply (point cloud) and mesh_distance.vtk and
// mesh_distance.vtp (legacy and XML VTK: the mesh the particles moved on,
// with the distance from each vertex to its nearest particle).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "mesh/surface_mesh.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// The names of the files of one run: an output directory holds these and nothing else.
inline const std::set<std::string> kRunOutputFiles = {"particles.particles", "particles.csv", "particles.ply",
                                                      "mesh_distance.vtk", "mesh_distance.vtp", "report.json"};

inline constexpr const char* kParticlesCsvHeader =
    "particle,vertex,x,y,z,corner_a,corner_b,corner_c,weight_a,weight_b,weight_c";

// Throws UserError, before the work, when `directory` could not be replaced
// by a run's files: its parent cannot be written, or it holds files that a
// run did not write (they would be lost).
void prepare_output_directory(const std::filesystem::path& directory);

// Every file of the result, put in place of `directory` at once; report.json
// is `report` with the other files' digests added. The files are written and
// digested side by side on at most `threads` threads (0: all cores).
void write_run_outputs(const std::filesystem::path& directory, const SurfaceMesh& mesh, const RunResult& result,
                       const nlohmann::json& report, unsigned threads = 1);

}  // namespace meshparticles
