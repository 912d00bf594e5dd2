#include "correspondence/population_correspondence.hpp"

#include "common/progress.hpp"
#include "correspondence/closest_surface_point.hpp"
#include "correspondence/joint_refinement.hpp"
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

// A shape aligned onto the template, and the template's particles carried
// onto its surface (the deformed template's, each to the nearest surface point).
ShapeCorrespondence transfer(const std::filesystem::path& file, const SurfaceMesh& mesh, const SurfaceMesh& template_mesh,
                             const PointSet& template_points, const Similarity& template_frame,
                             const std::vector<TemplateParticle>& template_particles, ShapeParticles& carried) {
  ShapeCorrespondence shape;
  shape.mesh = file;
  shape.vertices = mesh.vertex_count();
  shape.alignment = align_to_template(mesh, template_points, template_frame);
  const PointSet world = vertex_points(mesh);
  const PointSet common = shape.alignment.to_common.apply(world);
  const PointTree tree(common);
  const VertexTriangles around = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  const PointSet deformed = deform_template(template_mesh, template_points, common);
  const SurfaceWalk walk(mesh);
  carried.mesh = &mesh;
  for (const TemplateParticle& particle : template_particles) {
    Eigen::RowVector3d query = Eigen::RowVector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) query += particle.weights[k] * deformed.row(Eigen::Index(particle.corners[k]));
    const SurfaceHit hit = closest_surface_point(mesh, around, common, tree, query);
    // The same weights of the corners in the shape's own coordinates, reached
    // from a triangle of the first corner (the hit's triangle is next to it).
    const Eigen::RowVector3d at = hit.weights[0] * world.row(hit.corners[0]) + hit.weights[1] * world.row(hit.corners[1]) +
                                  hit.weights[2] * world.row(hit.corners[2]);
    std::uint32_t triangle = 0;
    walk.first_triangle(hit.corners[0], triangle);
    carried.at.push_back(walk.walk(triangle, {at(0), at(1), at(2)}));
  }
  return shape;
}

// Where the particles ended: their triangles, weights and positions in the
// file's terms, and how evenly they cover the shape.
void settle(ShapeCorrespondence& shape, const SurfaceMesh& mesh, const ShapeParticles& particles, bool quiet) {
  shape.particles.resize(Eigen::Index(particles.at.size()), 3);
  for (std::size_t i = 0; i < particles.at.size(); ++i) {
    const SurfaceLocation& at = particles.at[i];
    const Triangle& corners = mesh.triangles()[at.triangle];
    ShapeLocation location;
    std::size_t heaviest = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      location.corners[k] = mesh.input_id(corners[k]);
      location.weights[k] = at.weights[k];
      if (at.weights[k] > at.weights[heaviest]) heaviest = k;
    }
    location.vertex = location.corners[heaviest];
    shape.locations.push_back(location);
    shape.particles.row(Eigen::Index(i)) << at.at.x, at.at.y, at.at.z;
  }
  shape.quality = evenness(shape.mesh, mesh, shape.particles, quiet);
}

}  // namespace

PopulationCorrespondence correspond_population(const CorrespondRequest& request) {
  PopulationCorrespondence population;
  const std::filesystem::path& template_file = request.meshes.front();
  RunRequest run = request.run;
  run.mesh_label = template_file.string();
  run.quiet = request.quiet;
  std::vector<SurfaceMesh> meshes;
  meshes.reserve(request.meshes.size());  // the particles hold pointers to them
  meshes.push_back(load_mesh(template_file, request.quiet, {}));
  const SurfaceMesh& template_mesh = meshes.front();
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

  // Every mesh stays loaded: the joint refinement moves all shapes' particles together.
  std::vector<ShapeParticles> particles(request.meshes.size());
  ProgressLine progress("correspond", request.meshes.size(), request.quiet);
  for (std::size_t s = 0; s < request.meshes.size(); ++s) {
    if (s > 0) meshes.push_back(load_mesh(request.meshes[s], request.quiet, {}));
    population.shapes.push_back(transfer(request.meshes[s], meshes[s], template_mesh, template_points, template_frame,
                                         template_particles, particles[s]));
    progress.update(s + 1);
  }
  progress.finish();
  population.refinement = refine_jointly(particles, request.refinement, request.quiet);
  for (std::size_t s = 0; s < request.meshes.size(); ++s) {
    settle(population.shapes[s], meshes[s], particles[s], request.quiet);
  }
  return population;
}

}  // namespace meshparticles
