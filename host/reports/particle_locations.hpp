#pragma once
// Where each particle of a run lies on the input surface: as a point of the
// input mesh (a triangle of it and weights), and as the output files give
// it (its point, the nearest input vertex, and the triangle's corners by
// their file ids with the weights) - whether the run moved particles on the
// input's vertices (paper) or on a refined copy of the surface (spread).
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

struct ParticleLocation {
  Vec3 at;
  VertexId input_vertex = 0;  // the nearest vertex of the input (a paper run's own), its file id
  InputLocation on_input;     // at = the weighted sum of its corners, up to rounding
};

// Per particle, in order: its place on `input` (a triangle of `input`).
std::vector<SurfaceLocation> particles_on_input(const SurfaceMesh& input, const RunResult& result);

std::vector<ParticleLocation> particle_locations(const SurfaceMesh& input, const RunResult& result);

}  // namespace meshparticles
