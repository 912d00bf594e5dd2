#pragma once
// The template bent onto a shape by an embedded deformation graph (Sumner,
// Schmid, Pauly, SIGGRAPH 2007; the annealed weights of Li, Sumner, Pauly,
// SGP 2008): a fit that can follow a joint, where a smoothed displacement
// (template_deformation) cannot, since it pays for differences of
// displacement, which grow with the distance from the joint times the angle.
//
// Nodes are geodesic farthest points of the template; node j carries an
// affine map A_j and a translation t_j, and a template vertex v moves to
//   v' = sum_j w_j(v) [A_j (v - g_j) + g_j + t_j]
// over its k geodesically nearest nodes, w_j = (1 - d_j / d_max)^2
// normalised, d_max the distance to the (k+1)-th nearest. Minimised, by
// Gauss-Newton over the 12 unknowns of every node:
//   E_rot = sum_j  (c_a . c_b)^2 over column pairs + (c_a . c_a - 1)^2
//   E_reg = sum over edges (j, k), both ways, |A_j (g_k - g_j) + g_j + t_j - (g_k + t_k)|^2
//   E_fit = point-to-plane and a little point-to-point distance of the
//           moved template to the shape, both ways (each template vertex to
//           its nearest shape vertex, each shape vertex to its nearest moved
//           template vertex), pairs whose normals differ by over 60 degrees left out.
// E_reg costs nothing where neighbouring nodes share one rotation, so only a
// joint pays. Its edges join nodes whose geodesic Voronoi regions share a
// mesh edge (the restricted Delaunay graph), never straight-line
// neighbours: an arm resting on the torso would be welded to it.
// The weights of E_rot and E_reg start high (the whole shape moves nearly
// rigidly while the closest points are far off) and are halved stage by
// stage down to a floor.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

struct DeformationGraphOptions {
  // Nodes: the template's vertex count over `vertices_per_node`, clamped to
  // [min_nodes, max_nodes] (and to the vertex count). About 25 vertices a
  // node keeps each node's fit determined by many closest points while a
  // 5k-vertex body gets 200 nodes, some ten across a limb's length.
  std::size_t vertices_per_node = 25;
  std::size_t min_nodes = 32;
  std::size_t max_nodes = 300;
  std::size_t nodes_per_vertex = 4;  // k, 1 to 8
  // Weights, in units where a node's share of the fit weighs `fit` and
  // lengths are measured in node spacings (so the same numbers serve any
  // scale and resolution).
  double fit = 1;
  double point_to_point = 0.1;  // beside the point-to-plane term's 1
  double max_normal_angle_degrees = 60;
  // E_reg's weight, halved stage by stage from `smooth_start` while it is
  // at least `smooth_floor`; E_rot's is `rigid_ratio` times it. On the bent
  // family (12 shapes, n = 256) a ratio of 10 and a floor of 0.5 left
  // particle i's spread at 0.107 / 0.219 spacings (median / 90th
  // percentile, seed 6), these 0.093 / 0.168; a point-to-point weight of 1
  // 0.157 / 0.217. E_rot resists a stretch as much as a shear: the lower
  // it ends, the more each node may stretch with the shape. FAUST's people
  // (n = 256, the transfer alone) at a last stage of 0.125: 0.364 / 0.493,
  // the two people shaped least like the template slid about a spacing up
  // the body; 1/32: 0.319 / 0.446; 1/128: 0.307 / 0.420; 1/256: 0.276 /
  // 0.394. More nodes (12 vertices a node), 12 fits a stage or a final
  // stage at point-to-point weight 1 each gained under 0.02.
  double smooth_start = 64;
  double smooth_floor = 1.0 / 256;
  double rigid_ratio = 1;
  // Closest points recomputed (one Gauss-Newton step each) at most this
  // often a stage; a stage ends sooner once no vertex moves by more than
  // `settled` node spacings.
  int iterations_per_stage = 6;
  double settled = 1e-4;
  // Where a guide is given (deform_by_graph's `guide`: a shape vertex for
  // each template vertex), the stages whose E_reg weight is above this pull
  // each template vertex towards its guide's vertex instead of the nearest
  // points: the template carried through a motion a closest-point fit does
  // not find (a bend reversed), before the closest points take over. On
  // bent-either with every open pose chosen canonically (n = 256), guiding
  // the stages above 8 left three shapes 57 to 73 degrees off (spread
  // 2.44 / 3.00 spacings); above 1, none (1.11 / 1.42, one shape whose
  // canonical choice was wrong 180 degrees off).
  double guided_above = 1;
};

// A node for each 100 vertices (32 to 64), at most 4 fits a stage, its
// stiffness ending at 0.125: a fit whose residual compares the poses a
// rigid fit leaves open, after the large motion is out (about a third of
// the full fit's time on a capsule of 1,730 vertices). With fewer than 32
// nodes (or a higher smooth floor) the capsule's 80-degree joint was not
// followed.
DeformationGraphOptions coarse_deformation_graph_options();

// The graph on a mesh (the template as it lies in the common frame).
struct DeformationGraph {
  std::vector<VertexId> nodes;                              // g_j = the mesh's vertex nodes[j]
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // node pairs (a < b), sorted
  // Vertex v's nodes and their weights (summing to 1):
  // influence_nodes[influence_offsets[v] .. influence_offsets[v + 1]).
  std::vector<std::uint32_t> influence_offsets;
  std::vector<std::uint32_t> influence_nodes;
  std::vector<double> influence_weights;
  double spacing = 0;  // sqrt(area / nodes): the unit the weights are in
};

DeformationGraph build_deformation_graph(const SurfaceMesh& mesh, const DeformationGraphOptions& options = {});

// The graph on `template_mesh` as it lies at `template_points` (ids as its
// vertices): built once, it bends the template onto any number of shapes.
DeformationGraph template_graph(const SurfaceMesh& template_mesh, const PointSet& template_points,
                                const DeformationGraphOptions& options = {});

struct GraphFit {
  PointSet moved;          // the template's vertices on the shape, ids as the template's
  double rms = 0;          // of the distances to the other surface, both ways (below)
  std::size_t nodes = 0;
};

// `template_points`: the template's vertices (ids and triangles as
// `template_mesh`), `shape_points`: the shape's (triangles as
// `shape_mesh`'s; only its triangles are read), both in the common frame.
// The rms is over every template vertex's distance to the shape's surface
// and every shape vertex's to the moved template's.
GraphFit deform_by_graph(const SurfaceMesh& template_mesh, const PointSet& template_points,
                         const SurfaceMesh& shape_mesh, const PointSet& shape_points,
                         const DeformationGraphOptions& options = {});

// The same with the template's graph given (template_graph of these
// template points, at these options).
// `guide`, where given: a shape vertex for each template vertex
// (DeformationGraphOptions::guided_above).
GraphFit deform_by_graph(const DeformationGraph& graph, const SurfaceMesh& template_mesh,
                         const PointSet& template_points, const SurfaceMesh& shape_mesh, const PointSet& shape_points,
                         const DeformationGraphOptions& options = {}, const std::vector<Eigen::Index>* guide = nullptr);

}  // namespace meshparticles
