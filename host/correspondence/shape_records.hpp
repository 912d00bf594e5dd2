#pragma once
// A shape's results and the refinement's record as JSON: what a rank sends
// the others under mpirun, and what a checkpoint keeps for a resume. Every
// double reads back as it was (nlohmann::json writes the shortest text that
// does), so a result rebuilt from them is the same to the bit.
//
// What a checkpoint gives back is checked before it is used: the readers
// below that take a mesh's sizes throw std::invalid_argument naming the first
// value no run on that mesh could have written (an id past its end, a row
// short, barycentric weights outside [0, 1] or not summing to 1), and
// nlohmann::json's exceptions on a missing or mistyped field.
#include <vector>

#include <nlohmann/json.hpp>

#include "correspondence/joint_refinement.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/shape_correspondence.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/surface_location.hpp"

namespace meshparticles {

// Throws unless `weights` are a point's barycentric weights as a run
// writes them: each in [0, 1] and summing to 1, to rounding.
void check_barycentric(const std::array<double, 3>& weights);

// Throws unless `recorded` (an entry's "mesh") names `mesh`: an entry of
// one shape is not taken for another's.
void check_entry_mesh(const nlohmann::json& recorded, const std::string& mesh);

nlohmann::json locations_json(const std::vector<SurfaceLocation>& locations);
// `particles` locations on a mesh of `triangles` triangles.
std::vector<SurfaceLocation> locations_from_json(const nlohmann::json& json, std::size_t triangles,
                                                 std::size_t particles);

nlohmann::json runner_up_json(const MeshAlignment::RunnerUp& runner_up);
// null where the relief did not choose the pose (one pose open, or a body's turn).
nlohmann::json relief_json(const MeshAlignment::Relief& relief);
nlohmann::json alignment_json(const MeshAlignment& alignment);
MeshAlignment alignment_from_json(const nlohmann::json& json);

// Everything a ShapeCorrespondence holds.
nlohmann::json shape_json(const ShapeCorrespondence& shape);
ShapeCorrespondence shape_from_json(const nlohmann::json& json);
// Throws unless `json` is a shape of `particles` particles on `mesh`, of `vertices` vertices.
void check_shape_json(const nlohmann::json& json, const std::string& mesh, std::size_t vertices,
                      std::size_t particles);

nlohmann::json topology_json(const MeshTopology& topology);
MeshTopology topology_from_json(const nlohmann::json& json);

nlohmann::json refinement_json(const JointRefinementRecord& record);
JointRefinementRecord refinement_from_json(const nlohmann::json& json);

}  // namespace meshparticles
