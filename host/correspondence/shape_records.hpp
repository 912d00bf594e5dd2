#pragma once
// A shape's results and the refinement's record as JSON: what a rank sends
// the others under mpirun, and what a checkpoint keeps for a resume. Every
// double reads back as it was (nlohmann::json writes the shortest text that
// does), so a result rebuilt from them is the same to the bit.
#include <vector>

#include <nlohmann/json.hpp>

#include "correspondence/joint_refinement.hpp"
#include "correspondence/population_correspondence.hpp"

namespace meshparticles {

nlohmann::json locations_json(const std::vector<SurfaceLocation>& locations);
std::vector<SurfaceLocation> locations_from_json(const nlohmann::json& json);

nlohmann::json alignment_json(const MeshAlignment& alignment);
MeshAlignment alignment_from_json(const nlohmann::json& json);

// Everything a ShapeCorrespondence holds.
nlohmann::json shape_json(const ShapeCorrespondence& shape);
ShapeCorrespondence shape_from_json(const nlohmann::json& json);

nlohmann::json refinement_json(const JointRefinementRecord& record);
JointRefinementRecord refinement_from_json(const nlohmann::json& json);

}  // namespace meshparticles
