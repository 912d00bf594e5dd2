#include "correspondence/pose_choice.hpp"

#include <cstddef>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "common/parallel_for.hpp"
#include "common/shared_progress.hpp"
#include "correspondence/body_turn.hpp"
#include "correspondence/canonical_pose.hpp"
#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/relief_pose.hpp"

namespace meshparticles {

namespace {

// Every owned shape's first pose: its fit onto the template where that
// leaves one pose open, else the one of those in which the template's
// relief lands on the shape's (relief_pose); where none lays it surely
// (sure_relief), the pose its canonical form chooses (canonical_pose) if
// none lays it (weak_relief) or the canonical form lays it better, whose
// pairs then guide the shape's deformation (`poses.guides`). A shape
// `turned_by_body` keeps its fit's pose (choose_body_turns turns it later).
// Each owner decides its own shapes: the same choice on any number of
// threads or processes.
void first_poses(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                 const Similarity& template_frame, const PointSet& template_points,
                 const std::vector<char>& turned_by_body, const PoseChoiceOptions& options, bool quiet,
                 PopulationPoses& found) {
  const std::vector<std::size_t> owned = share.owned();
  const PointsTree template_tree(template_points);
  const ReliefTemplate relief_template(*meshes.front(), template_points, options);
  // The template's canonical form, made for the first shape that needs it.
  std::once_flag canonical_side;
  std::optional<CanonicalTemplate> canonical_template;
  std::vector<MeshAlignment>& alignments = found.alignments;
  SharedProgress fitting("align", owned.size(), quiet);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    const PoseTrials trials = pose_trials(*meshes[k], template_points, template_frame, template_tree, options);
    const std::vector<std::size_t> open =
        k == 0 || turned_by_body[k] ? std::vector{trials.chosen} : trials.distinct_poses(options);
    std::vector<MeshAlignment> poses;
    for (const std::size_t trial : open) poses.push_back(fit_pose(trials, trial, template_points, template_tree, options));
    if (poses.size() == 1) {
      alignments[k] = poses.front();
    } else {
      const ReliefChoice choice = choose_pose_by_relief(relief_template, *meshes[k], poses);
      alignments[k] = poses[choice.chosen];
      alignments[k].relief = choice.relief;
      if (choice.relief.agreement < options.sure_relief) {
        // No open pose lays the relief surely after the coarse fit: the
        // canonical form is asked too. Under weak_relief it chooses (FAUST's
        // arms overhead); else where it lays the relief better (a body bent
        // the other way, which the coarse fit cannot unbend). Its pairs then
        // carry the template.
        std::call_once(canonical_side, [&] { canonical_template.emplace(*meshes.front(), template_points, options); });
        std::optional<CanonicalPose> pose = choose_pose_canonically(*canonical_template, *meshes[k]);
        if (pose && (choice.relief.agreement < options.weak_relief ||
                     pose->alignment.relief.agreement > choice.relief.agreement)) {
          alignments[k] = pose->alignment;
          found.guides[k] = std::move(pose->pairs);
        }
      }
    }
    fitting.advance();
  });
  fitting.finish();
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

// The shape nearest the others (the medoid) as a second reference: each
// shape whose fit left one pose open, the template too (unless it is a
// body), takes its pose onto the medoid where that lies clearly nearer the
// whole population (nearer_population); one the relief or the canonical
// form chose keeps it and follows the template. A template whose radii or
// pose differ from most shapes' then pulls them less. Every process
// gathers every shape's aligned points (its rotation first) and chooses the
// same medoid. `template_points` follow the template where it moves.
void choose_medoid_poses(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                         const Similarity& template_frame, PointSet& template_points, bool body_template,
                         const std::vector<char>& turned_by_body, const PoseChoiceOptions& options,
                         std::vector<MeshAlignment>& alignments) {
  const std::size_t count = meshes.size();
  const std::vector<std::size_t> owned = share.owned();
  const SurfaceMesh& template_mesh = *meshes.front();
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
  if (medoid == 0) return;
  // The medoid's pose as given stands for the template's in the first start.
  Similarity medoid_frame;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) medoid_frame.rotation(r, c) = aligned_message[medoid][std::size_t(3 * r + c)];
  }
  const PointSet& reference = aligned.shape(medoid);
  // Each shape keeps the pose, onto the template or onto the medoid, that
  // lies nearer the whole population (as first aligned).
  const auto realign = [&](std::size_t k, const SurfaceMesh& mesh, const MeshAlignment& first) {
    MeshAlignment again = align_to_template(mesh, reference, medoid_frame, options);
    const PointSet points = alignment_points(mesh);
    const double before = aligned.distance_to_population(first.to_common.apply(points), k);
    const double after = aligned.distance_to_population(again.to_common.apply(points), k);
    return clearly_lower(after, before, options.nearer_population) ? std::optional(again) : std::nullopt;
  };
  const std::optional<MeshAlignment> template_again =
      body_template ? std::nullopt
                    : realign(0, template_mesh, align_to_template(template_mesh, template_points, template_frame, options));
  if (template_again) template_points = template_again->to_common.apply(vertex_points(template_mesh));
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    if (turned_by_body[k]) return;
    if (alignments[k].relief.measured) {
      // Its pose is the template's, chosen by the relief or carried by the
      // canonical pairs: it moves where the template moves. A rigid fit
      // onto the medoid, judged by the silhouette, would overrule what the
      // relief chose (bent-either: a shape bent the template's way turned
      // half round onto a medoid bent the other).
      if (template_again) alignments[k].to_common = follow(template_frame, template_again->to_common, alignments[k].to_common);
      return;
    }
    const std::optional<MeshAlignment> again = k == 0 ? template_again : realign(k, *meshes[k], alignments[k]);
    if (again) alignments[k] = *again;
  });
}

}  // namespace

PopulationPoses choose_population_poses(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                                        const Similarity& template_frame, PointSet& template_points,
                                        const PoseChoiceOptions& options, bool quiet) {
  const std::size_t count = meshes.size();
  const std::vector<std::size_t> owned = share.owned();
  const bool body_template = ellipsoid_body(template_points).has_value();
  std::vector<char> turned_by_body(count, 0);
  for_each_index(owned, share.threads(), [&](std::size_t k) {
    turned_by_body[k] = k != 0 && body_template && ellipsoid_body(vertex_points(*meshes[k])).has_value();
  });
  PopulationPoses found;
  found.alignments.resize(count);
  found.guides.resize(count);
  first_poses(meshes, share, template_frame, template_points, turned_by_body, options, quiet, found);
  choose_medoid_poses(meshes, share, template_frame, template_points, body_template, turned_by_body, options,
                      found.alignments);
  choose_body_turns(meshes, share, template_points, found.alignments, options);
  return found;
}

}  // namespace meshparticles
