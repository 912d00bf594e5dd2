#pragma once
// Particles that correspond across a population (issue 31, first part):
// the template (the first shape) is sampled by the default run (spread);
// every shape is brought into the template's frame (mesh_alignment); each
// template particle then goes to the nearest vertex of each shape not yet
// taken (particle order decides), so particle i sits at the same place,
// up to how well the shapes fit, on every shape. The joint optimisation
// that would also keep each shape evenly spread (ShapeWorks' entropy
// system) is not done yet: docs/CORRESPONDENCE.md.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

struct CorrespondRequest {
  std::vector<std::filesystem::path> meshes;  // the first is the template
  RunRequest run;                             // the template's run (-n, seed, method, ...)
  bool quiet = false;
};

struct ShapeCorrespondence {
  std::filesystem::path mesh;
  std::size_t vertices = 0;
  MeshAlignment alignment;
  std::vector<VertexId> particle_vertices;  // per particle: a vertex of this shape, its id in the file
  PointSet particles;                       // their positions, the shape's own coordinates
  std::size_t shared = 0;                   // particles that found no free vertex near and share one
};

struct PopulationCorrespondence {
  RunResult template_run;
  std::vector<ShapeCorrespondence> shapes;
};

// Throws UserError for a mesh that cannot be read (naming it) and for -n
// above the vertices of any shape.
PopulationCorrespondence correspond_population(const CorrespondRequest& request);

}  // namespace meshparticles
