#include "correspondence/population_correspondence.hpp"

#include <algorithm>

#include "common/progress.hpp"
#include "common/user_error.hpp"
#include "correspondence/point_tree.hpp"
#include "pipeline/mesh_input.hpp"
#include "reports/particle_locations.hpp"

namespace meshparticles {

namespace {

// Nearest vertices looked at for a free one before sharing.
constexpr std::size_t kFreeVertexSearch = 32;

ShapeCorrespondence transfer(const std::filesystem::path& file, const SurfaceMesh& mesh, const PointSet& template_points,
                             const Similarity& template_frame, const PointSet& template_particles) {
  ShapeCorrespondence shape;
  shape.mesh = file;
  shape.vertices = mesh.vertex_count();
  shape.alignment = align_to_template(mesh, template_points, template_frame);
  const PointSet world = vertex_points(mesh);
  const PointSet common = shape.alignment.to_common.apply(world);
  const PointTree tree(common);
  std::vector<bool> taken(mesh.vertex_count(), false);
  shape.particles.resize(template_particles.rows(), 3);
  for (Eigen::Index i = 0; i < template_particles.rows(); ++i) {
    const std::vector<Eigen::Index> near = tree.nearest(template_particles.row(i), kFreeVertexSearch);
    const auto free = std::find_if(near.begin(), near.end(), [&](Eigen::Index v) { return !taken[std::size_t(v)]; });
    const Eigen::Index chosen = free != near.end() ? *free : near.front();
    if (free == near.end()) ++shape.shared;
    taken[std::size_t(chosen)] = true;
    shape.particle_vertices.push_back(mesh.input_id(VertexId(chosen)));
    shape.particles.row(i) = world.row(chosen);
  }
  return shape;
}

}  // namespace

PopulationCorrespondence correspond_population(const CorrespondRequest& request) {
  PopulationCorrespondence population;
  const std::filesystem::path& template_file = request.meshes.front();
  RunRequest run = request.run;
  run.mesh_label = template_file.string();
  run.quiet = request.quiet;
  const SurfaceMesh template_mesh = load_mesh(template_file, request.quiet, {});
  population.template_run = run_pipeline(template_mesh, run);

  // The template's frame is the common one: its canonical frame.
  const Similarity template_frame = canonical_frame(template_mesh);
  const PointSet template_points = template_frame.apply(vertex_points(template_mesh));
  const std::vector<ParticleLocation> locations = particle_locations(template_mesh, population.template_run);
  PointSet template_particles(Eigen::Index(locations.size()), 3);
  for (std::size_t i = 0; i < locations.size(); ++i) {
    template_particles.row(Eigen::Index(i)) << locations[i].at.x, locations[i].at.y, locations[i].at.z;
  }
  template_particles = template_frame.apply(template_particles);

  ProgressLine progress("correspond", request.meshes.size(), request.quiet);
  for (std::size_t s = 0; s < request.meshes.size(); ++s) {
    const SurfaceMesh mesh = s == 0 ? template_mesh : load_mesh(request.meshes[s], request.quiet, {});
    if (mesh.vertex_count() < std::size_t(template_particles.rows())) {
      throw UserError(request.meshes[s].string() + ": " + std::to_string(mesh.vertex_count()) +
                      " vertices, fewer than the " + std::to_string(template_particles.rows()) + " particles");
    }
    population.shapes.push_back(transfer(request.meshes[s], mesh, template_points, template_frame, template_particles));
    progress.update(s + 1);
  }
  progress.finish();
  return population;
}

}  // namespace meshparticles
