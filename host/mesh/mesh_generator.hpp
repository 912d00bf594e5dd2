#pragma once
// The project's own test meshes, generated deterministically so anyone can
// regenerate meshes/ bit for bit (`meshparticles generate`). The large shapes
// imitate the output of an FEM mesher: a coarse base mesh refined by splitting
// its longest edges, then Delaunay edge flips and smoothing with projection
// back onto the analytic surface, which leaves irregular valences.
#include <string>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Names accepted by generate_mesh, in the order `generate` writes them.
const std::vector<std::string>& generated_mesh_names();

// Throws UserError for an unknown name.
SurfaceMesh generate_mesh(const std::string& name);

}  // namespace meshparticles
