#pragma once
// The project's own test meshes, generated deterministically so anyone can
// regenerate meshes/ bit for bit (`meshparticles generate`). The large shapes
// imitate the output of an FEM mesher: a coarse base mesh refined by splitting
// its longest edges, then Delaunay edge flips and smoothing with projection
// back onto the analytic surface, which leaves irregular valences.
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Names accepted by generate_mesh, in the order `generate` writes them.
const std::vector<std::string>& generated_mesh_names();

// Throws UserError for an unknown name.
SurfaceMesh generate_mesh(const std::string& name);

// The meshes that come at any size, for benchmarks on large meshes (not
// committed): "sphere" and "atrium".
const std::vector<std::string>& scalable_mesh_names();

// `name` with about `vertices` vertices: the geodesic sphere of the nearest
// frequency f (10 f^2 + 2 vertices), projected onto the shape and improved
// like the committed meshes, without their final refinement to an exact
// count (which costs a pass over all edges per vertex added). Throws
// UserError for a name that does not scale or fewer than 12 vertices.
SurfaceMesh generate_mesh_at(const std::string& name, std::size_t vertices);

// An atrium-like shape of a population: the committed atrium's body and
// bulges, each moved, resized and reshaped at random from `seed`, the whole
// scaled by 0.8 to 1.2, at about `vertices` vertices as generate_mesh_at.
SurfaceMesh generate_atrium_variant(std::uint64_t seed, std::size_t vertices);

}  // namespace meshparticles
