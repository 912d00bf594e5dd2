#include "correspondence/population_correspondence.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "common/json_text.hpp"
#include "common/parallel_for.hpp"
#include "common/shared_progress.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "correspondence/deformation_graph.hpp"
#include "correspondence/geodesic_repair.hpp"
#include "correspondence/joint_refinement.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/population_doubts.hpp"
#include "correspondence/pose_choice.hpp"
#include "correspondence/shape_records.hpp"
#include "correspondence/template_deformation.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_on_triangle.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "mesh/vertex_triangles.hpp"
#include "particles/particle_params.hpp"
#include "particles/surface_voronoi.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/point_set_measurement.hpp"
#include "pipeline/run_pipeline.hpp"
#include "pipeline/spread_method.hpp"
#include "reports/particle_locations.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

// The particles measured as `run` measures its own (through the balls of
// kSpreadQualityCutoff around them, wider where a particle is alone there),
// on the shape's own surface refined until they lie on vertices, while its
// mesh is loaded. A shape's figures and its own run's are then the same measure.
DistributionQuality evenness(const std::filesystem::path& file, const SurfaceMesh& mesh, const PointSet& particles,
                             unsigned threads) {
  PointSetsRequest request;
  request.names = {file.string()};
  request.points.emplace_back();
  for (Eigen::Index i = 0; i < particles.rows(); ++i) {
    request.points.back().push_back({particles(i, 0), particles(i, 1), particles(i, 2)});
  }
  request.geodesics.quiet = true;  // the stage's progress line counts the shapes
  request.geodesics.threads = threads;
  request.geodesics.cache_directory.reset();
  request.distances.kind = StoreKind::local;
  request.distances.cutoff = kSpreadQualityCutoff;
  DistributionQuality quality = measure_point_sets(mesh, request).sets.front().quality;
  if (quality.alone == 0) return quality;
  request.distances.cutoff = kSpreadWideQualityCutoff;
  return measure_point_sets(mesh, request).sets.front().quality;
}

// A shape aligned onto the template, and the template's particles carried
// onto its surface (the deformed template's, each to the nearest point of
// the surface, found exactly in the shape's own coordinates: a similarity
// keeps the nearest point nearest). The template's particles are points of
// its triangles by their corners' weights, so that they follow it as it
// deforms: by `graph`, the template's deformation graph, or where that is
// null by the smoothed displacement (template_deformation).
ShapeCorrespondence transfer(const std::filesystem::path& file, const SurfaceMesh& mesh, const SurfaceMesh& template_mesh,
                             const PointSet& template_points, const MeshAlignment& alignment,
                             const std::vector<SurfaceLocation>& template_particles, const DeformationGraph* graph,
                             const std::vector<Eigen::Index>* guide, ShapeParticles& carried) {
  ShapeCorrespondence shape;
  shape.mesh = file;
  shape.vertices = mesh.vertex_count();
  shape.topology = mesh_topology(mesh);
  shape.alignment = alignment;
  const Similarity& to_common = shape.alignment.to_common;
  const Eigen::Matrix3d& stretch = shape.alignment.stretch;
  const PointSet common = (to_common.apply(vertex_points(mesh)) * stretch.transpose()).rowwise() +
                          shape.alignment.shift.transpose();
  const PointSet deformed = graph ? deform_by_graph(*graph, template_mesh, template_points, mesh, common, {}, guide).moved
                                 : deform_template(template_mesh, template_points, common);
  const Eigen::Matrix3d unstretch = stretch.inverse();
  const NearestSurfacePoint nearest(mesh);
  carried.mesh = &mesh;
  for (const SurfaceLocation& particle : template_particles) {
    const Triangle& corners = template_mesh.triangles()[particle.triangle];
    Eigen::RowVector3d query = Eigen::RowVector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) query += particle.weights[k] * deformed.row(Eigen::Index(corners[k]));
    const Eigen::RowVector3d unstretched = (query - shape.alignment.shift.transpose()) * unstretch.transpose();
    const Eigen::RowVector3d own = (unstretched - to_common.translation.transpose()) * to_common.rotation / to_common.scale;
    // A loaded mesh has triangles (mesh_checks refuses one without area).
    carried.at.push_back(nearest.find({own(0), own(1), own(2)}).value());
  }
  return shape;
}

// Where the particles ended: their triangles, weights and positions in the
// file's terms, and how evenly they cover the shape.
void settle(ShapeCorrespondence& shape, const SurfaceMesh& mesh, const ShapeParticles& particles, unsigned threads) {
  shape.particles.resize(Eigen::Index(particles.at.size()), 3);
  for (std::size_t i = 0; i < particles.at.size(); ++i) {
    const SurfaceLocation& at = particles.at[i];
    const Triangle& corners = mesh.triangles()[at.triangle];
    InputLocation location;
    for (std::size_t k = 0; k < 3; ++k) {
      location.corners[k] = mesh.input_id(corners[k]);
      location.weights[k] = at.weights[k];
    }
    shape.locations.push_back(location);
    shape.particles.row(Eigen::Index(i)) << at.at.x, at.at.y, at.at.z;
  }
  shape.quality = evenness(shape.mesh, mesh, shape.particles, threads);
}

// The template's particles as doubles (its triangle's corners, as template
// vertex ids, then the weights), for the other processes and the checkpoint.
std::vector<double> template_message(const SurfaceMesh& template_mesh, const std::vector<SurfaceLocation>& particles) {
  std::vector<double> message;
  for (const SurfaceLocation& particle : particles) {
    for (const VertexId corner : template_mesh.triangles()[particle.triangle]) message.push_back(double(corner));
    message.insert(message.end(), particle.weights.begin(), particle.weights.end());
  }
  return message;
}

// A message's particles as points of the template, each corners' triangle
// found (std::invalid_argument for corners no triangle of it has, in that
// order, as no run writes). The corners are whole numbers of vertex ids.
std::vector<SurfaceLocation> template_from_message(const SurfaceMesh& template_mesh, const std::vector<double>& message) {
  const VertexTriangles around = vertex_triangles(template_mesh.triangles(), template_mesh.vertex_count());
  const auto& positions = template_mesh.positions();
  std::vector<SurfaceLocation> particles(message.size() / 6);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    Triangle corners{};
    for (std::size_t k = 0; k < 3; ++k) {
      corners[k] = VertexId(message[6 * i + k]);
      particles[i].weights[k] = message[6 * i + 3 + k];
    }
    const auto candidates = around.around(corners[0]);
    const auto holder = std::find_if(candidates.begin(), candidates.end(),
                                     [&](std::uint32_t t) { return template_mesh.triangles()[t] == corners; });
    if (holder == candidates.end()) {
      throw std::invalid_argument("corners " + std::to_string(corners[0]) + ", " + std::to_string(corners[1]) + ", " +
                                  std::to_string(corners[2]) + " are no triangle of the template");
    }
    particles[i].triangle = *holder;
    particles[i].at = at_weights(particles[i].weights, positions[corners[0]], positions[corners[1]], positions[corners[2]]);
  }
  return particles;
}

// The template's particles as a checkpoint keeps them, checked against the
// template and the -n asked before they are used (std::invalid_argument).
std::vector<SurfaceLocation> template_from_checkpoint(const nlohmann::json& kept, const SurfaceMesh& template_mesh,
                                                      std::size_t particles, DistributionQuality& quality) {
  const std::vector<double> message = kept.at("particles").get<std::vector<double>>();
  if (message.empty() || message.size() % 6 != 0) {
    throw std::invalid_argument(std::to_string(message.size()) + " numbers, not 6 per particle");
  }
  if (message.size() / 6 != particles) {
    throw std::invalid_argument(std::to_string(message.size() / 6) + " particles, not the " +
                                std::to_string(particles) + " of -n");
  }
  for (std::size_t i = 0; i < message.size(); ++i) {
    const double value = message[i];
    const bool corner = i % 6 < 3;
    const bool valid = corner ? value >= 0 && value < double(template_mesh.vertex_count()) && value == std::floor(value)
                              : std::isfinite(value);
    if (!valid) throw std::invalid_argument((corner ? "vertex " : "weight ") + nlohmann::json(value).dump());
  }
  for (std::size_t i = 0; i < message.size(); i += 6) {
    check_barycentric({message[i + 3], message[i + 4], message[i + 5]});
  }
  quality = quality_from_json(kept.at("quality"), message.size() / 6);
  return template_from_message(template_mesh, message);
}

// The template's run (or the checkpoint's), on the leader: its particles as
// points of the template, and its quality.
std::vector<SurfaceLocation> sample_template(const SurfaceMesh& template_mesh, const PopulationRequest& request,
                                             const CorrespondCheckpoint* checkpoint, DistributionQuality& quality) {
  if (checkpoint) {
    const auto kept = checkpoint->read("template", [&](const nlohmann::json& values) {
      return template_from_checkpoint(values, template_mesh, request.run.particles, quality);
    });
    if (kept) return *kept;
  }
  RunRequest run = request.run;
  if (run.method != Method::paper) {  // spread's working mesh, at the template's resolution
    run.vertices_per_particle = run.vertices_per_particle.value_or(kTemplateVerticesPerParticle);
    run.longest_edge = run.longest_edge.value_or(kTemplateLongestEdge);
  }
  run.mesh_label = request.meshes.front().string();
  run.quiet = request.quiet;
  const RunResult result = run_pipeline(template_mesh, run);
  quality = result.quality;
  std::vector<SurfaceLocation> particles = particles_on_input(template_mesh, result);
  if (checkpoint) {
    checkpoint->write("template", {{"particles", template_message(template_mesh, particles)},
                                   {"quality", quality_json(quality)}});
  }
  return particles;
}

// A refinement stage ("iterated", "packed"): taken from the checkpoint where
// an earlier run finished it, else run and kept. Every process takes the same
// branch. Each shape's entry names its mesh (`meshes`, the request's).
void refinement_stage(const std::string& stage, std::vector<ShapeParticles>& particles, std::size_t particle_count,
                      const std::vector<std::filesystem::path>& meshes, ShapeShare& share,
                      const CorrespondCheckpoint* checkpoint, JointRefinementRecord& record,
                      const std::function<void()>& run) {
  const auto kept = checkpoint ? checkpoint->read(stage, refinement_from_json) : std::nullopt;
  if (kept) {
    for (const std::size_t k : share.owned()) {
      const SurfaceMesh& mesh = *particles[k].mesh;
      auto shape = checkpoint->read(shape_entry(stage, k), [&](const nlohmann::json& values) {
        check_entry_mesh(values.at("mesh"), meshes[k].string());
        return locations_from_json(values.at("locations"), mesh.triangle_count(), particle_count);
      });
      if (!shape) {
        throw UserError("checkpoint stage " + stage + " lacks shape " + std::to_string(k) + ": remove " +
                        CorrespondCheckpoint::kFolder + "/ and run again");
      }
      particles[k].at = std::move(*shape);
    }
    record = *kept;
    return;
  }
  run();
  if (!checkpoint) return;
  for (const std::size_t k : share.owned()) {
    checkpoint->write(shape_entry(stage, k),
                      {{"mesh", meshes[k].string()}, {"locations", locations_json(particles[k].at)}});
  }
  std::vector<std::vector<double>> written(share.shapes());
  share.gather(written);  // every shape's file is written before the stage's record
  if (share.leads()) checkpoint->write(stage, refinement_json(record));
}

// What the result cannot promise, said once per shape on stderr and kept
// for summary.json: a shape of another topology than the template's still
// gets particles, but particle i cannot mean the same place on both (a
// torus's hole has no match on a sphere), and the model's modes describe
// the mismatch; a shape whose pose another fits almost as well may lie turned.
void warn_of_doubts(PopulationCorrespondence& population, const PoseChoiceOptions& poses, bool quiet) {
  for (std::string& line : population_doubts(population.shapes, poses)) {
    if (!quiet) std::cerr << "meshparticles: warning: " << line << "\n";
    population.warnings.push_back(std::move(line));
  }
}

}  // namespace

PopulationCorrespondence correspond_population(const PopulationRequest& request) {
  ShapeShare share(request.meshes.size());
  return correspond_population(request, share, nullptr);
}

PopulationCorrespondence correspond_population(const PopulationRequest& request, ShapeShare& share,
                                               const CorrespondCheckpoint* checkpoint) {
  PopulationCorrespondence population;
  const std::size_t count = request.meshes.size();
  // Every process holds the template; the others, their owners. The
  // particles hold pointers into `meshes`, which is never resized.
  std::vector<std::optional<SurfaceMesh>> meshes(count);
  meshes.front().emplace(load_mesh(request.meshes.front(), request.quiet, {}));
  const SurfaceMesh& template_mesh = *meshes.front();

  // The leader samples the template and tells the others.
  std::vector<SurfaceLocation> template_particles;
  if (share.leads()) {
    template_particles = sample_template(template_mesh, request, checkpoint, population.template_quality);
  }
  std::vector<double> message = template_message(template_mesh, template_particles);
  share.broadcast(message);
  template_particles = template_from_message(template_mesh, message);
  const std::size_t particle_count = template_particles.size();

  // The template's frame is the common one: its canonical frame.
  const Similarity template_frame = canonical_frame(template_mesh);
  PointSet template_points = template_frame.apply(vertex_points(template_mesh));

  const std::vector<std::size_t> owned = share.owned();
  // Each process loads its own shapes (the template it holds already).
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    if (!meshes[k]) meshes[k].emplace(load_mesh(request.meshes[k], request.quiet, {}));
  });
  // Every owned shape's pose, and its canonical pairs where they chose it.
  const PopulationPoses poses =
      choose_population_poses(meshes, share, template_frame, template_points, request.poses, request.quiet);
  const std::vector<MeshAlignment>& alignments = poses.alignments;
  const std::vector<std::vector<Eigen::Index>>& guides = poses.guides;
  // The template's side of the transfer, made for the first shape not
  // resumed from the checkpoint (none, where every shape is).
  std::once_flag template_side;
  std::optional<DeformationGraph> graph;
  TemplateGeodesics template_distances;
  const auto make_template_side = [&] {
    if (request.deformation == TemplateDeformation::graph) graph = template_graph(template_mesh, template_points);
    template_distances = template_geodesics(template_mesh, template_particles);
  };

  // Each process's shapes, each on a thread: the template carried onto them.
  population.shapes.resize(count);
  std::vector<ShapeParticles> particles(count);
  SharedProgress transferring("correspond", owned.size(), request.quiet);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const SurfaceMesh& mesh = *meshes[k];
    const auto transferred = [&](const nlohmann::json& values) {
      check_entry_mesh(values.at("mesh"), request.meshes[k].string());
      return std::tuple(alignment_from_json(values.at("alignment")),
                        locations_from_json(values.at("locations"), mesh.triangle_count(), particle_count),
                        values.at("repaired").get<std::size_t>());
    };
    const auto kept = checkpoint ? checkpoint->read(shape_entry("transfer", k), transferred) : std::nullopt;
    if (kept) {
      ShapeCorrespondence& shape = population.shapes[k];
      shape.mesh = request.meshes[k];
      shape.vertices = mesh.vertex_count();
      shape.topology = mesh_topology(mesh);
      shape.alignment = std::get<0>(*kept);
      particles[k] = {&mesh, std::get<1>(*kept)};
      shape.repaired = std::get<2>(*kept);
    } else {
      std::call_once(template_side, make_template_side);
      population.shapes[k] = transfer(request.meshes[k], *meshes[k], template_mesh, template_points, alignments[k],
                                      template_particles, graph ? &*graph : nullptr,
                                      guides[k].empty() ? nullptr : &guides[k], particles[k]);
      if (k != 0) population.shapes[k].repaired = repair_by_geodesics(template_distances, mesh, particles[k].at).moved;
      if (checkpoint) {
        checkpoint->write(shape_entry("transfer", k), {{"mesh", request.meshes[k].string()},
                                                       {"alignment", alignment_json(population.shapes[k].alignment)},
                                                       {"repaired", population.shapes[k].repaired},
                                                       {"locations", locations_json(particles[k].at)}});
      }
    }
    transferring.advance();
  });
  transferring.finish();

  std::vector<std::vector<SurfaceLocation>> transferred(count);  // where the refinement's moves start
  for (const std::size_t k : owned) transferred[k] = particles[k].at;
  const std::vector<std::filesystem::path>& paths = request.meshes;  // what each shape's entry names
  refinement_stage("iterated", particles, particle_count, paths, share, checkpoint, population.refinement, [&] {
    iterate_jointly(particles, particle_count, request.refinement, share, population.refinement, request.quiet);
  });
  refinement_stage("packed", particles, particle_count, paths, share, checkpoint, population.refinement, [&] {
    pack_jointly(particles, particle_count, request.refinement, share, population.refinement, request.quiet);
    hold_back_evening(particles, transferred, particle_count, widest_hole_spacings(template_mesh, template_particles),
                      request.refinement, share, population.refinement);
  });

  // Each shape measured on its own surface; then every process holds every shape's result.
  SharedProgress measuring("measure", owned.size(), request.quiet);
  const unsigned measure_threads = std::max(1u, share.threads() / unsigned(std::max<std::size_t>(owned.size(), 1)));
  std::vector<std::string> results(count);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const auto settled = [&](const nlohmann::json& values) {
      check_shape_json(values, request.meshes[k].string(), meshes[k]->vertex_count(), particle_count);
      return values;
    };
    const auto kept = checkpoint ? checkpoint->read(shape_entry("settled", k), settled) : std::nullopt;
    if (kept) {
      results[k] = json_text(*kept);
    } else {
      settle(population.shapes[k], *meshes[k], particles[k], measure_threads);
      const nlohmann::json result = shape_json(population.shapes[k]);
      if (checkpoint) checkpoint->write(shape_entry("settled", k), result);
      results[k] = json_text(result);
    }
    measuring.advance();
  });
  measuring.finish();
  share.gather(results);
  for (std::size_t k = 0; k < count; ++k) population.shapes[k] = shape_from_json(nlohmann::json::parse(results[k]));
  warn_of_doubts(population, request.poses, request.quiet);
  return population;
}

}  // namespace meshparticles
