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
#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "correspondence/body_turn.hpp"
#include "correspondence/canonical_pose.hpp"
#include "correspondence/deformation_graph.hpp"
#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/geodesic_repair.hpp"
#include "correspondence/joint_refinement.hpp"
#include "correspondence/population_doubts.hpp"
#include "correspondence/relief_pose.hpp"
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

// A shape takes its pose onto the medoid only where that lies this much
// nearer the population than its pose onto the template: where the two are
// about as near, the template's is kept (and the output as it was).
constexpr double kNearerPopulation = 1.02;

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

// The widest hole `particles` leave on `mesh`, in hexagonal spacings, as
// the geodesic Voronoi diagram at the vertices measures it (the template's:
// what hold_back_evening holds every shape's holes to).
double widest_hole(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& particles) {
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  return surface_voronoi(mesh, *solver, particles, scratch).cover() / hexagonal_spacing(mesh.area(), particles.size());
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

// A progress line that the threads of a stage advance together.
class SharedProgress {
 public:
  SharedProgress(const char* label, std::size_t total, bool quiet) : line_(label, total, quiet) {}
  void advance() {
    const std::lock_guard lock(mutex_);
    line_.update(++done_);
  }
  void finish() { line_.finish(); }

 private:
  std::mutex mutex_;
  ProgressLine line_;
  std::size_t done_ = 0;
};

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
void warn_of_doubts(PopulationCorrespondence& population, bool quiet) {
  for (std::string& line : population_doubts(population.shapes)) {
    if (!quiet) std::cerr << "meshparticles: warning: " << line << "\n";
    population.warnings.push_back(std::move(line));
  }
}

// Every owned shape's first pose: its fit onto the template where that
// leaves one pose open, else the one of those in which the template's
// relief lands on the shape's (relief_pose); where none lays it surely
// (kSureRelief), the pose its canonical form chooses (canonical_pose) if
// none lays it (kWeakRelief) or the canonical form lays it better, whose
// pairs then guide the shape's deformation (`guides`). A shape
// `turned_by_body` keeps its fit's pose (choose_body_turns turns it later).
// Each owner decides its own shapes: the same choice on any number of
// threads or processes.
std::vector<MeshAlignment> first_poses(const PopulationRequest& request, const std::vector<std::optional<SurfaceMesh>>& meshes,
                                       ShapeShare& share, const Similarity& template_frame,
                                       const PointSet& template_points, const std::vector<char>& turned_by_body,
                                       std::vector<std::vector<Eigen::Index>>& guides) {
  const std::vector<std::size_t> owned = share.owned();
  const PointsTree template_tree(template_points);
  const ReliefTemplate relief_template(*meshes.front(), template_points);
  // The template's canonical form, made for the first shape that needs it.
  std::once_flag canonical_side;
  std::optional<CanonicalTemplate> canonical_template;
  std::vector<MeshAlignment> alignments(meshes.size());
  SharedProgress fitting("align", owned.size(), request.quiet);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const PoseTrials trials = pose_trials(*meshes[k], template_points, template_frame, template_tree);
    const std::vector<std::size_t> open =
        k == 0 || turned_by_body[k] ? std::vector{trials.chosen} : trials.distinct_poses(kOpenPoseRatio);
    std::vector<MeshAlignment> poses;
    for (const std::size_t trial : open) poses.push_back(fit_pose(trials, trial, template_points, template_tree));
    if (poses.size() == 1) {
      alignments[k] = poses.front();
    } else {
      const ReliefChoice choice =
          choose_pose_by_relief(relief_template, *meshes[k], poses);
      alignments[k] = poses[choice.chosen];
      alignments[k].relief = choice.relief;
      if (choice.relief.agreement < kSureRelief) {
        // No open pose lays the relief surely after the coarse fit: the
        // canonical form is asked too. Under kWeakRelief it chooses (FAUST's
        // arms overhead); else where it lays the relief better (a body bent
        // the other way, which the coarse fit cannot unbend). Its pairs then
        // carry the template.
        std::call_once(canonical_side, [&] { canonical_template.emplace(*meshes.front(), template_points); });
        std::optional<CanonicalPose> pose = choose_pose_canonically(*canonical_template, *meshes[k]);
        if (pose && (choice.relief.agreement < kWeakRelief || pose->alignment.relief.agreement > choice.relief.agreement)) {
          alignments[k] = pose->alignment;
          guides[k] = std::move(pose->pairs);
        }
      }
    }
    fitting.advance();
  });
  fitting.finish();
  return alignments;
}

// `pose` (into the frame where the template lies at `from`) into the frame
// where it lies at `to`.
Similarity follow(const Similarity& from, const Similarity& to, const Similarity& pose) {
  const Eigen::Matrix3d turn = to.rotation * from.rotation.transpose();
  const double grow = to.scale / from.scale;
  Similarity moved;
  moved.scale = grow * pose.scale;
  moved.rotation = turn * pose.rotation;
  moved.translation = grow * (turn * (pose.translation - from.translation)) + to.translation;
  return moved;
}

// Every owned shape's pose in the common frame (loading its mesh). A first
// pose (first_poses); then the shape nearest the others (the medoid) is a
// second reference, and each shape whose fit left one pose open, the
// template too, takes its pose onto the medoid where that lies clearly
// nearer the whole population (one the relief or the canonical form chose
// keeps it and follows the template): a
// template whose radii or pose differ from most shapes' then pulls them
// less. Every process gathers every shape's aligned points (its rotation
// first) and chooses the same medoid. Shapes with an ellipsoid body, where
// the template has one, take their turn from the population's features
// (choose_body_turns). `template_points` follow the template where it moves.
std::vector<MeshAlignment> align_population(const PopulationRequest& request,
                                            std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                                            const Similarity& template_frame, PointSet& template_points,
                                            std::vector<std::vector<Eigen::Index>>& guides) {
  const std::size_t count = meshes.size();
  const std::vector<std::size_t> owned = share.owned();
  const SurfaceMesh& template_mesh = *meshes.front();
  const bool body_template = ellipsoid_body(template_points).has_value();
  std::vector<char> turned_by_body(count, 0);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    if (!meshes[k]) meshes[k].emplace(load_mesh(request.meshes[k], request.quiet, {}));
    turned_by_body[k] = k != 0 && body_template && ellipsoid_body(vertex_points(*meshes[k])).has_value();
  });
  std::vector<MeshAlignment> alignments =
      first_poses(request, meshes, share, template_frame, template_points, turned_by_body, guides);
  std::vector<std::vector<double>> aligned_message(count);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const PointSet placed = alignments[k].to_common.apply(alignment_points(*meshes[k]));
    std::vector<double>& shape_message = aligned_message[k];
    const Eigen::Matrix3d& rotation = alignments[k].to_common.rotation;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) shape_message.push_back(rotation(r, c));
    }
    for (Eigen::Index i = 0; i < placed.rows(); ++i) {
      for (int c = 0; c < 3; ++c) shape_message.push_back(placed(i, c));
    }
  });
  share.gather(aligned_message);
  std::vector<PointSet> aligned_points(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::vector<double>& shape_message = aligned_message[k];
    PointSet& points = aligned_points[k];
    points.resize(Eigen::Index((shape_message.size() - 9) / 3), 3);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      for (int c = 0; c < 3; ++c) points(i, c) = shape_message[9 + std::size_t(3 * i + c)];
    }
  }
  const AlignedShapes aligned(std::move(aligned_points));
  const std::size_t medoid = aligned.medoid();
  if (medoid != 0) {
    // The medoid's pose as given stands for the template's in the first start.
    Similarity medoid_frame;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) medoid_frame.rotation(r, c) = aligned_message[medoid][std::size_t(3 * r + c)];
    }
    const PointSet& reference = aligned.shape(medoid);
    // Each shape keeps the pose, onto the template or onto the medoid,
    // that lies nearer the whole population (as first aligned).
    const auto realign = [&](std::size_t k, const SurfaceMesh& mesh, const MeshAlignment& first) {
      MeshAlignment again = align_to_template(mesh, reference, medoid_frame);
      const PointSet points = alignment_points(mesh);
      const double before = aligned.distance_to_population(first.to_common.apply(points), k);
      const double after = aligned.distance_to_population(again.to_common.apply(points), k);
      return after * kNearerPopulation < before ? std::optional(again) : std::nullopt;
    };
    const std::optional<MeshAlignment> template_again =
        body_template ? std::nullopt
                      : realign(0, template_mesh, align_to_template(template_mesh, template_points, template_frame));
    if (template_again) template_points = template_again->to_common.apply(vertex_points(template_mesh));
    for_each_index(owned, share.threads(), [&](std::size_t k) {
      if (turned_by_body[k]) return;
      if (alignments[k].relief.measured) {
        // Its pose is the template's, chosen by the relief or carried by the
        // canonical pairs: it moves where the template moves. A rigid fit
        // onto the medoid, judged by the silhouette, would overrule what
        // the relief chose (bent-either: a shape bent the template's way
        // turned half round onto a medoid bent the other).
        if (template_again) alignments[k].to_common = follow(template_frame, template_again->to_common, alignments[k].to_common);
        return;
      }
      const std::optional<MeshAlignment> again = k == 0 ? template_again : realign(k, *meshes[k], alignments[k]);
      if (again) alignments[k] = *again;
    });
  }
  choose_body_turns(meshes, share, template_points, alignments);
  return alignments;
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
  std::vector<std::vector<Eigen::Index>> guides(count);  // a shape's canonical pairs, where they chose its pose
  const std::vector<MeshAlignment> alignments =
      align_population(request, meshes, share, template_frame, template_points, guides);
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
    hold_back_evening(particles, transferred, particle_count, widest_hole(template_mesh, template_particles),
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
  warn_of_doubts(population, request.quiet);
  return population;
}

}  // namespace meshparticles
