#pragma once
// Which pose a shape takes on the template, chosen where bending plays no
// part: in the shapes' intrinsic *canonical forms* (Elad and Kimmel 2003).
// Bending keeps geodesic distances, so a body bent one way and the same
// body bent the other way have one canonical form: the surface embedded in
// 3-D so that straight distances stand for its geodesic ones, by classical
// multidimensional scaling of the geodesic distances between landmarks
// (geodesic farthest points), every vertex then placed by its distances to
// the landmarks (landmark MDS, de Silva and Tenenbaum 2004). The embedding's
// mirror image is ruled out by the mesh's own orientation.
//
// In canonical space the shape's form is fitted rigidly onto the
// template's from many starts; the ends of those fits that lie as near as
// the best are told apart by the template's relief (surface_relief, less
// its slow trend: bumps, a nose, hands) at each template vertex's
// canonically nearest shape vertex. The pose in the shape's own space is
// the rigid motion (Kabsch) that lays those pairs (template vertex, its
// canonically nearest shape vertex) over each other, and the pairs guide
// the deformation graph's stiff stages (deform_by_graph's `guide`), which
// carries the template through a bend reversed. correspond takes it where
// no pose the rigid fit leaves open lays the relief after a coarse
// deformable fit (relief_pose's agreement under weak_relief: FAUST's arms
// overhead, bent-either's bodies bent the other way from the template).
//
// Measured limits (n = 256): the bent families' bend is not isometric
// (the outer side stretched by the body's radius over the arc's, up to
// 26%), so a body bent the other way keeps a mirrored stretch and some bend
// in its canonical form; the quadratic trend along the long axis is taken
// out (`straighten`) and the relief's slow trend too, after which 10 of
// bent-either's 11 shapes pair right. On FAUST's poses the canonical pairs
// lie about 2.6 spacings off, and front is told from back less surely than
// after the coarse deformable fit: chosen canonically wherever several poses
// are open, 3 of 9 poses and one of FAUST's people end turned.
#include <cstddef>
#include <optional>
#include <vector>

#include "correspondence/mesh_alignment.hpp"
#include "correspondence/pose_choice_options.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// A mesh's canonical form: its vertices embedded (ids as the mesh's) at
// unit area, centred, along their principal axes; nothing where the mesh
// has vertices no landmark reaches (several components).
std::optional<PointSet> canonical_form(const SurfaceMesh& mesh, const CanonicalPoseOptions& options = {});

// The template's side, the same for every shape (its form made by
// `options.canonical`).
struct CanonicalTemplate {
  CanonicalTemplate(const SurfaceMesh& template_mesh, const PointSet& template_points, const PoseChoiceOptions& options);
  const SurfaceMesh& mesh;
  PointSet points;  // in the common frame
  std::optional<PointSet> form;
  Eigen::VectorXd relief;
  PoseChoiceOptions options;
};

struct CanonicalPose {
  MeshAlignment alignment;  // the pose (Kabsch on the pairs); `relief` says how the choice went
  // Each template vertex's canonically nearest shape vertex.
  std::vector<Eigen::Index> pairs;
};

// Nothing where either form could not be made.
std::optional<CanonicalPose> choose_pose_canonically(const CanonicalTemplate& reference, const SurfaceMesh& mesh);

}  // namespace meshparticles
