#pragma once
// Shapes of a population brought into one frame before their particles are
// matched: each mesh scaled to unit area and centred, then iterative closest
// points onto the template, from the pose as given and from the shape's own
// principal axes (area-weighted second moments, signed by the third moments)
// onto the template's in each of the 24 proper ways (signs and orders). Each
// start is judged by a short affine fit, so that radii which vary from shape
// to shape do not outvote the features that place it; the best start's pose
// is then fitted rigidly. The given pose is kept where it ends in the best
// start's pose or fits almost as well; where other poses fit almost as well
// too, the template's relief chooses among them after a coarse deformable
// fit in each (relief_pose). Shapes may
// arrive in any position, size and orientation. The best start that ends in
// another pose is reported: where it fits almost as well, the shape's
// geometry cannot tell the two poses apart.
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "correspondence/pose_choice_options.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "mesh/surface_mesh.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles {

// A mesh's vertices as a PointSet.
PointSet vertex_points(const SurfaceMesh& mesh);

// The 24 turns that take the coordinate axes onto themselves (the cube's
// rotations): every signed permutation of determinant +1, the identity's
// order first. The ways one shape's principal axes can lie on another's.
const std::vector<Eigen::Matrix3d>& cube_rotations();

// The angle of the turn from rotation `a` to rotation `b`, in degrees.
double turn_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

// Unit area, centroid at 0, principal axes along x, y, z (largest first).
Similarity canonical_frame(const SurfaceMesh& mesh);

struct MeshAlignment {
  Similarity to_common;  // the mesh's coordinates -> the common (template's canonical) frame
  // In the common frame, after to_common: x -> stretch x + shift, which lays
  // an ellipsoid body's radii onto the template's (choose_body_turns); the
  // identity for other shapes. The template is deformed onto the shape so
  // stretched, and its particles carried back.
  Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  // The root mean square distance from its vertices to the template's
  // nearest, in the common frame (unit area): how well it fits.
  double rms = 0;
  std::size_t iterations = 0;
  bool from_principal_axes = false;  // else from the pose as given
  // The best start that ended in another pose than the chosen one
  // (PoseChoiceOptions::same_pose_degrees or more from it),
  // after the same short affine fit: its rms over the chosen's (infinite:
  // none), and the angle between the two poses.
  struct RunnerUp {
    double rms_ratio = std::numeric_limits<double>::infinity();
    double degrees = 0;
    double rms = std::numeric_limits<double>::infinity();
  } runner_up;
  // Where the fit left several poses open and the template's relief chose
  // among them (relief_pose): the correlation of the template's relief with
  // the shape's after a coarse deformable fit in the chosen pose, and in the
  // best pose whose fit ends elsewhere (-infinity: none), that pose's turn
  // from the chosen.
  struct Relief {
    bool measured = false;
    double agreement = 0;
    double runner_up = -std::numeric_limits<double>::infinity();
    double runner_up_degrees = 0;
    // Told in canonical form (canonical_pose), not after the coarse fit
    // (relief_pose): where no pose the fit left open laid the relief.
    bool canonical = false;
  } relief;
};

// The vertices an alignment fits: all, or every k-th of a large mesh.
PointSet alignment_points(const SurfaceMesh& mesh);

// At most `most` rows of `points`, evenly strided from the first (all where
// there are no more).
PointSet strided_rows(const PointSet& points, std::size_t most);

using PointsTree = MatrixRowTree<PointSet>;

// The mean squared distance from `a`'s points to `b`'s nearest.
double mean_squared_to_nearest(const PointSet& a, const PointSet& b, const PointsTree& b_tree);

// The symmetric rms distance between two shapes' points (each to the
// other's nearest, the two means of squares averaged).
double shape_distance(const PointSet& a, const PointsTree& a_tree, const PointSet& b, const PointsTree& b_tree);

// A population's shapes as first aligned (each a shape's alignment_points
// in the common frame), with a k-d tree over each, built once for the
// medoid and for every shape's distance to the population (searched from
// many threads at once: the searches only read).
class AlignedShapes {
 public:
  explicit AlignedShapes(std::vector<PointSet> aligned);
  AlignedShapes(const AlignedShapes&) = delete;  // the trees read the shapes where they are
  AlignedShapes& operator=(const AlignedShapes&) = delete;

  std::size_t size() const { return shapes_.size(); }
  const PointSet& shape(std::size_t k) const { return shapes_[k]; }

  // The shape nearest the others: the least sum of the symmetric rms
  // distances to the nearest points (ties: the first). For one reference
  // every process finds the same from the same points.
  std::size_t medoid() const;

  // The sum of those distances from `placed` (a shape's alignment_points in
  // the common frame) to every shape but `self`.
  double distance_to_population(const PointSet& placed, std::size_t self) const;

 private:
  std::vector<PointSet> shapes_;
  std::vector<std::unique_ptr<PointsTree>> trees_;
};

// One start of a shape's fit onto the template: the similarity it starts
// from, and the short affine fit that follows it.
struct PoseTrial {
  Similarity start;  // the mesh's coordinates -> the common frame, before the fit
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();  // the affine fit: x -> linear x + translation
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rms = 0;  // from the fitted points to the template's nearest
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();  // the pose it ends in (the fit's nearest rotation, after the start)
};

// Every start of a shape (the pose as given first, then the 24 turns of its
// principal axes onto the template's), each fitted.
struct PoseTrials {
  PointSet points;  // the vertices fitted (alignment_points), in the mesh's coordinates
  std::vector<PoseTrial> trials;
  std::size_t best = 0;    // the least rms
  std::size_t chosen = 0;  // the best, or the pose as given where it ends there or fits almost as well
  // The chosen trial, then the best trial of every other pose (ending at
  // least same_pose_degrees from those before it) whose rms is within
  // open_pose_ratio times the best's, least rms first: the poses the
  // shape's own fit onto the template cannot rule out.
  std::vector<std::size_t> distinct_poses(const PoseChoiceOptions& options) const;
};

// Of candidate fits (their rms and the turns they end in), `kept` and then,
// least rms first (ties: the earlier), each whose rms is within `within`
// times the least and whose turn lies at least `degrees` from every one
// taken before it: the distinct poses that fit about as well as the best.
// The trials' open poses (PoseTrials::distinct_poses) and the canonical
// fits' (canonical_pose).
std::vector<std::size_t> distinct_poses(const std::vector<double>& rms, const std::vector<Eigen::Matrix3d>& turns,
                                        std::vector<std::size_t> kept, double within, double degrees);

// The candidate whose agreement is highest (ties: the earlier), and as a
// Relief (measured) its agreement and the best other's whose end is not
// `same_end(c, chosen)`'s (ties: the earlier; -infinity: none), with the
// angle from `turns[chosen]` to its turn. The relief's choice among the
// open poses (relief_pose) and among the canonical fits (canonical_pose).
template <typename SameEnd>
std::size_t choose_by_agreement(const std::vector<double>& agreements, const std::vector<Eigen::Matrix3d>& turns,
                                SameEnd&& same_end, MeshAlignment::Relief& relief) {
  std::size_t chosen = 0;
  for (std::size_t c = 1; c < agreements.size(); ++c) {
    if (agreements[c] > agreements[chosen]) chosen = c;
  }
  relief.measured = true;
  relief.agreement = agreements[chosen];
  for (std::size_t c = 0; c < agreements.size(); ++c) {
    if (same_end(c, chosen) || !(agreements[c] > relief.runner_up)) continue;
    relief.runner_up = agreements[c];
    relief.runner_up_degrees = turn_angle(turns[c], turns[chosen]);
  }
  return chosen;
}

// `template_points`: the template's vertices in the common frame, which
// `template_frame` (its canonical_frame) defines; `template_tree` over them.
PoseTrials pose_trials(const SurfaceMesh& mesh, const PointSet& template_points, const Similarity& template_frame,
                       const PointsTree& template_tree, const PoseChoiceOptions& options);

// The pose of trial `chosen`, fitted rigidly onto the template from its
// start, and its runner-up among the other trials.
MeshAlignment fit_pose(const PoseTrials& trials, std::size_t chosen, const PointSet& template_points,
                       const PointsTree& template_tree, const PoseChoiceOptions& options);

// pose_trials, then fit_pose of the chosen trial.
MeshAlignment align_to_template(const SurfaceMesh& mesh, const PointSet& template_points,
                                const Similarity& template_frame, const PoseChoiceOptions& options);

}  // namespace meshparticles
