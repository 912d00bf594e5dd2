#pragma once
// Which way round a shape's ellipsoid body lies against another's: of the 24
// turns that take one body's axes onto the other's (the cube's rotations),
// the one that lays the shapes' features (what stands off the body: a
// bump, a knob) over each other's. Compared on each body's unit sphere, so
// that radii, which differ from shape to shape and may swap order, play no
// part; and by correlation, so that a small feature over a large one still
// counts as a match.
#include <cstddef>
#include <optional>
#include <vector>

#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_choice_options.hpp"
#include "correspondence/shape_share.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// Directions spread evenly over the unit sphere (a Fibonacci lattice), and
// for each cube rotation T (cube_rotations) and each direction g, the
// direction nearest T g: made once for every profile compared on it.
struct ProfileGrid {
  PointSet directions;
  std::vector<std::vector<Eigen::Index>> turned;  // [turn][direction]
};
ProfileGrid profile_grid(std::size_t count);

// How far `points` stand off `body`'s unit sphere (its radius less 1) at
// each of `grid`'s directions (in the body's frame): the nearest point's.
Eigen::VectorXd feature_profile(const EllipsoidBody& body, const PointSet& points, const PointSet& grid);

// A profile's agreement with `reference` (on the same grid, in the
// reference's frame) under each cube rotation T (the profile's direction
// g lies at T g there): the grid mean of the product.
std::vector<double> turn_agreements(const Eigen::VectorXd& profile, const Eigen::VectorXd& reference,
                                    const ProfileGrid& grid);

// `profile` seen in the reference's frame through cube rotation `turn`.
Eigen::VectorXd turned_profile(const Eigen::VectorXd& profile, const ProfileGrid& grid, std::size_t turn);

// Where the template (its vertices in the common frame: `template_points`)
// is an ellipsoid body, each other shape with one (of at least 3) takes the
// cube rotation of its body onto the template's whose features agree best
// with the rest of the population's, each in its turn as chosen so far
// (rounds in the shapes' order until none changes, at most
// body_turn_rounds; a turn held gives way only to one clearly_better_turn;
// the first turns are those nearest the shapes' poses in `alignments`). A shape whose features
// are faint, or whose knob stands where the template's bump does, is then
// placed by all the others rather than by the template alone. Its pose:
// that turn, its body's centre on the template's; its stretch: its body's
// radii onto the template's. Every process gathers every shape's profile
// and chooses the same turns; each sets its own shapes' alignments.
void choose_body_turns(const std::vector<std::optional<SurfaceMesh>>& meshes, ShapeShare& share,
                       const PointSet& template_points, std::vector<MeshAlignment>& alignments,
                       const PoseChoiceOptions& options);

}  // namespace meshparticles
