#include "correspondence/population_correspondence.hpp"

#include "common/progress.hpp"
#include "correspondence/closest_surface_point.hpp"
#include "correspondence/point_tree.hpp"
#include "correspondence/template_deformation.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/point_sets.hpp"
#include "reports/particle_locations.hpp"

namespace meshparticles {

namespace {

// The particles measured as `quality` measures a file, on the shape's own
// surface (refined until they lie on vertices), while its mesh is loaded.
DistributionQuality evenness(const std::filesystem::path& file, const SurfaceMesh& mesh, const PointSet& particles,
                             bool quiet) {
  PointSetsRequest request;
  request.names = {file.string()};
  request.points.emplace_back();
  for (Eigen::Index i = 0; i < particles.rows(); ++i) {
    request.points.back().push_back({particles(i, 0), particles(i, 1), particles(i, 2)});
  }
  request.geodesics.quiet = quiet;
  request.geodesics.cache_directory.reset();
  return measure_point_sets(mesh, request).sets.front().quality;
}

// The template's particles as its vertices' weights, so that they follow the template as it deforms.
struct TemplateParticle {
  Triangle corners{};  // template vertex ids
  std::array<double, 3> weights{};
};

ShapeCorrespondence transfer(const std::filesystem::path& file, const SurfaceMesh& mesh, const SurfaceMesh& template_mesh,
                             const PointSet& template_points, const Similarity& template_frame,
                             const std::vector<TemplateParticle>& template_particles, bool quiet) {
  ShapeCorrespondence shape;
  shape.mesh = file;
  shape.vertices = mesh.vertex_count();
  shape.alignment = align_to_template(mesh, template_points, template_frame);
  const PointSet world = vertex_points(mesh);
  const PointSet common = shape.alignment.to_common.apply(world);
  const PointTree tree(common);
  const VertexTriangles around = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  const PointSet deformed = deform_template(template_mesh, template_points, common);
  shape.particles.resize(Eigen::Index(template_particles.size()), 3);
  for (Eigen::Index i = 0; i < shape.particles.rows(); ++i) {
    const TemplateParticle& particle = template_particles[std::size_t(i)];
    Eigen::RowVector3d query = Eigen::RowVector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) query += particle.weights[k] * deformed.row(Eigen::Index(particle.corners[k]));
    const SurfaceHit hit = closest_surface_point(mesh, around, common, tree, query);
    SurfaceLocation location;
    std::size_t heaviest = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      location.corners[k] = mesh.input_id(hit.corners[k]);
      location.weights[k] = hit.weights[k];
      if (hit.weights[k] > hit.weights[heaviest]) heaviest = k;
    }
    location.vertex = location.corners[heaviest];
    shape.locations.push_back(location);
    // The same weights of the corners in the shape's own coordinates.
    shape.particles.row(i) = hit.weights[0] * world.row(hit.corners[0]) + hit.weights[1] * world.row(hit.corners[1]) +
                             hit.weights[2] * world.row(hit.corners[2]);
  }
  shape.quality = evenness(file, mesh, shape.particles, quiet);
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
  std::vector<TemplateParticle> template_particles;
  for (const ParticleLocation& location : locations) {
    TemplateParticle particle;
    for (std::size_t k = 0; k < 3; ++k) {
      particle.corners[k] = *template_mesh.vertex_of_input_id(location.corners[k]);
      particle.weights[k] = location.weights[k];
    }
    template_particles.push_back(particle);
  }

  ProgressLine progress("correspond", request.meshes.size(), request.quiet);
  for (std::size_t s = 0; s < request.meshes.size(); ++s) {
    const SurfaceMesh mesh = s == 0 ? template_mesh : load_mesh(request.meshes[s], request.quiet, {});
    population.shapes.push_back(transfer(request.meshes[s], mesh, template_mesh, template_points, template_frame,
                                         template_particles, request.quiet));
    progress.update(s + 1);
  }
  progress.finish();
  return population;
}

}  // namespace meshparticles
