#include "correspondence/deformation_graph.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Sparse>

#include "correspondence/vertex_fields.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/nearest_surface_point.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "particles/initial_placement.hpp"

namespace meshparticles {

namespace {

// The balls that find each vertex's nearest nodes reach this many covering
// radii: within 2 of them a vertex has some five nodes (farthest points lie
// at least a covering radius apart).
constexpr double kInfluenceReach = 3;
// Added to every diagonal entry of the normal equations (in node spacings):
// what keeps a node no closest point and no edge determines from moving.
constexpr double kDamping = 1e-6;
// Halvings of a Gauss-Newton step tried before a step is given up.
constexpr int kStepHalvings = 4;
// A step's normal equations are solved by conjugate gradients,
// preconditioned by the factorization of the stage's first matrix, to this
// residual (relative to the right-hand side's), in at most this many
// iterations; else the matrix is factorized afresh. Within a stage only
// the closest pairs and the rotations change the matrix, and a
// factorization was most of a fit's time (300 nodes: 3,600 unknowns, 1.3
// million entries in the factor; one a step took 2.6 times as long on
// shapes of 10,000 vertices).
constexpr double kSolveResidual = 1e-6;
constexpr int kMostSolveIterations = 30;
// The most nodes that move one vertex (DeformationGraphOptions::nodes_per_vertex).
constexpr std::size_t kMostNodesPerVertex = 8;

using Affine = Eigen::Matrix<double, 3, 4>;  // [A_j | t_j]: column-major, its 12 unknowns in order
using Block = Eigen::Matrix<double, 12, 12>;

std::size_t node_count(std::size_t vertices, const DeformationGraphOptions& options) {
  const std::size_t wanted = std::clamp(vertices / options.vertices_per_node, options.min_nodes, options.max_nodes);
  return std::min(wanted, vertices);
}

// The normal equations' blocks: one 12 x 12 block for each pair of nodes
// (j <= k) that share a vertex or an edge, found by binary search in j's
// sorted row.
class BlockMatrix {
 public:
  BlockMatrix(std::size_t nodes, std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs) : offsets_(nodes + 1, 0) {
    for (std::uint32_t j = 0; j < nodes; ++j) pairs.emplace_back(j, j);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [j, k] : pairs) {
      ++offsets_[j + 1];
      columns_.push_back(k);
    }
    for (std::size_t j = 0; j < nodes; ++j) offsets_[j + 1] += offsets_[j];
    blocks_.assign(columns_.size(), Block::Zero());
  }
  void clear() { std::fill(blocks_.begin(), blocks_.end(), Block::Zero()); }
  Block& at(std::uint32_t j, std::uint32_t k) {
    const auto first = columns_.begin() + offsets_[j], last = columns_.begin() + offsets_[j + 1];
    return blocks_[std::size_t(std::lower_bound(first, last, k) - columns_.begin())];
  }
  // The upper triangle, `damping` added to the diagonal.
  Eigen::SparseMatrix<double> upper(double damping) const {
    std::vector<Eigen::Triplet<double>> entries;
    for (std::uint32_t j = 0; j + 1 < offsets_.size(); ++j) {
      for (std::size_t b = offsets_[j]; b < offsets_[j + 1]; ++b) {
        const std::uint32_t k = columns_[b];
        for (int r = 0; r < 12; ++r) {
          for (int c = (k == j ? r : 0); c < 12; ++c) {
            entries.emplace_back(12 * j + r, 12 * k + c, blocks_[b](r, c) + (k == j && r == c ? damping : 0.0));
          }
        }
      }
    }
    const Eigen::Index size = Eigen::Index(12 * (offsets_.size() - 1));
    Eigen::SparseMatrix<double> matrix(size, size);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
  }

 private:
  std::vector<std::size_t> offsets_;
  std::vector<std::uint32_t> columns_;
  std::vector<Block> blocks_;
};

// A residual vector e = sum_p [A|t]_{node p} u_p + constant, weighted by W
// (3 x 3, symmetric): its share of the normal equations.
struct LinearTerm {
  std::array<std::uint32_t, kMostNodesPerVertex> nodes{};
  std::array<Eigen::Vector4d, kMostNodesPerVertex> u{};
  std::size_t size = 0;
};

void add_term(const LinearTerm& term, const Eigen::Vector3d& e, const Eigen::Matrix3d& weight, BlockMatrix& hessian,
              Eigen::VectorXd& gradient) {
  const Eigen::Vector3d we = weight * e;
  // Block (a, b) of each 12 x 12 gains u_p(a) u_q(b) W, in plain loops over
  // copies in arrays and the block's column-major storage: the same
  // products and sums as Eigen's 3 x 3 blocks, which unoptimised builds
  // (the sanitizer's -O1) ran 10x slower, most of correspond's tests there.
  double w[3][3];  // w[j][i] = W(i, j)
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) w[j][i] = weight(i, j);
  }
  double u[kMostNodesPerVertex][4];
  for (std::size_t p = 0; p < term.size; ++p) {
    for (int a = 0; a < 4; ++a) u[p][a] = term.u[p](a);
  }
  for (std::size_t p = 0; p < term.size; ++p) {
    for (int a = 0; a < 4; ++a) gradient.segment<3>(12 * term.nodes[p] + 3 * a) += u[p][a] * we;
    for (std::size_t q = 0; q < term.size; ++q) {
      if (term.nodes[p] > term.nodes[q]) continue;
      double* column = hessian.at(term.nodes[p], term.nodes[q]).data();
      for (int b = 0; b < 4; ++b) {
        for (int j = 0; j < 3; ++j, column += 12) {
          for (int a = 0; a < 4; ++a) {
            const double uv = u[p][a] * u[q][b];
            for (int i = 0; i < 3; ++i) column[3 * a + i] += uv * w[j][i];
          }
        }
      }
    }
  }
}

// Sumner's Rot(A): the columns' dot products, and each column's squared
// length less 1, as six residuals; `jacobian` their derivatives by A's nine
// entries (column-major).
Eigen::Matrix<double, 6, 1> rotation_residuals(const Affine& m, Eigen::Matrix<double, 6, 9>* jacobian) {
  static constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {1, 2}, {0, 0}, {1, 1}, {2, 2}};
  Eigen::Matrix<double, 6, 1> r;
  if (jacobian) jacobian->setZero();
  for (int i = 0; i < 6; ++i) {
    const int a = kPairs[i][0], b = kPairs[i][1];
    r(i) = m.col(a).dot(m.col(b)) - (a == b ? 1.0 : 0.0);
    if (!jacobian) continue;
    jacobian->block<1, 3>(i, 3 * a) += m.col(b).transpose();
    jacobian->block<1, 3>(i, 3 * b) += m.col(a).transpose();
  }
  return r;
}

// A template vertex pulled towards a shape point, in the plane of the
// shape's normal there.
struct FitPair {
  std::uint32_t vertex;
  Eigen::Vector3d target;
  Eigen::Vector3d normal;
};

// The fit of one graph: the template and shape in node spacings about the
// template's centroid, the nodes' maps, and the energy at the current weights.
class GraphSolve {
 public:
  GraphSolve(const DeformationGraph& graph, PointSet points, const DeformationGraphOptions& options)
      : graph_(graph), points_(std::move(points)), options_(options), maps_(graph.nodes.size()) {
    for (Affine& m : maps_) m << Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = graph.edges;
    for (std::size_t v = 0; v + 1 < graph.influence_offsets.size(); ++v) {
      for (std::uint32_t a = graph.influence_offsets[v]; a < graph.influence_offsets[v + 1]; ++a) {
        for (std::uint32_t b = graph.influence_offsets[v]; b < graph.influence_offsets[v + 1]; ++b) {
          const std::uint32_t j = graph.influence_nodes[a], k = graph.influence_nodes[b];
          if (j < k) pairs.emplace_back(j, k);
        }
      }
    }
    hessian_ = std::make_unique<BlockMatrix>(graph.nodes.size(), std::move(pairs));
  }

  Eigen::Vector3d node(std::uint32_t j) const { return points_.row(Eigen::Index(graph_.nodes[j])).transpose(); }

  Eigen::Vector3d moved_vertex(std::uint32_t v, const std::vector<Affine>& maps) const {
    const Eigen::Vector3d x = points_.row(Eigen::Index(v)).transpose();
    if (graph_.influence_offsets[v] == graph_.influence_offsets[v + 1]) return x;  // no node in its component
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::uint32_t a = graph_.influence_offsets[v]; a < graph_.influence_offsets[v + 1]; ++a) {
      const std::uint32_t j = graph_.influence_nodes[a];
      const Eigen::Vector3d g = node(j);
      sum += graph_.influence_weights[a] * (maps[j].leftCols<3>() * (x - g) + g + maps[j].col(3));
    }
    return sum;
  }
  PointSet moved_points() const {
    PointSet moved(points_.rows(), 3);
    for (Eigen::Index v = 0; v < moved.rows(); ++v) moved.row(v) = moved_vertex(std::uint32_t(v), maps_).transpose();
    return moved;
  }

  // One Gauss-Newton step at these pairs and weights, halved while it
  // raises the energy; false where no step lowers it.
  bool step(const std::vector<FitPair>& pairs, double smooth, double rigid) {
    set_weights(pairs, smooth, rigid);
    hessian_->clear();
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(Eigen::Index(12 * maps_.size()));
    for (const FitPair& pair : pairs) {
      LinearTerm term;
      const Eigen::Vector3d x = points_.row(Eigen::Index(pair.vertex)).transpose();
      for (std::uint32_t a = graph_.influence_offsets[pair.vertex]; a < graph_.influence_offsets[pair.vertex + 1]; ++a) {
        const std::uint32_t j = graph_.influence_nodes[a];
        term.nodes[term.size] = j;
        term.u[term.size++] << graph_.influence_weights[a] * (x - node(j)), graph_.influence_weights[a];
      }
      add_term(term, moved_vertex(pair.vertex, maps_) - pair.target, fit_weight(pair), *hessian_, gradient);
    }
    for (const auto& [a, b] : graph_.edges) {
      for (const auto& [j, k] : {std::pair(a, b), std::pair(b, a)}) {
        LinearTerm term;
        term.size = 2;
        term.nodes = {j, k};
        term.u[0] << node(k) - node(j), 1;
        term.u[1] << 0, 0, 0, -1;
        add_term(term, edge_residual(j, k, maps_), smooth_ * Eigen::Matrix3d::Identity(), *hessian_, gradient);
      }
    }
    for (std::uint32_t j = 0; j < maps_.size(); ++j) {
      Eigen::Matrix<double, 6, 9> jacobian;
      const Eigen::Matrix<double, 6, 1> r = rotation_residuals(maps_[j], &jacobian);
      hessian_->at(j, j).topLeftCorner<9, 9>() += rigid_ * jacobian.transpose() * jacobian;
      gradient.segment<9>(12 * j) += rigid_ * jacobian.transpose() * r;
    }
    const Eigen::SparseMatrix<double> matrix = hessian_->upper(kDamping);
    std::optional<Eigen::VectorXd> delta;
    if (solver_ && factored_smooth_ == smooth) delta = preconditioned_solve(matrix, -gradient);
    if (!delta) {
      if (!solver_) {
        solver_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper>>();
        solver_->analyzePattern(matrix);
      }
      solver_->factorize(matrix);
      if (solver_->info() != Eigen::Success) {
        solver_.reset();
        return false;
      }
      factored_smooth_ = smooth;
      delta = solver_->solve(-gradient);
    }
    const double before = energy(pairs, maps_);
    double length = 1;
    for (int halving = 0; halving <= kStepHalvings; ++halving, length /= 2) {
      std::vector<Affine> trial = maps_;
      for (std::size_t j = 0; j < trial.size(); ++j) {
        trial[j] += length * Eigen::Map<const Affine>(delta->data() + 12 * j);
      }
      if (energy(pairs, trial) <= before) {
        maps_ = std::move(trial);
        return true;
      }
    }
    return false;
  }

 private:
  // Conjugate gradients on `upper` (its upper triangle) x = b, from and
  // preconditioned by the factorization in `solver_`; nothing where they
  // do not reach kSolveResidual.
  std::optional<Eigen::VectorXd> preconditioned_solve(const Eigen::SparseMatrix<double>& upper,
                                                      const Eigen::VectorXd& b) const {
    const auto matrix = upper.selfadjointView<Eigen::Upper>();
    const double goal = kSolveResidual * b.norm();
    Eigen::VectorXd x = solver_->solve(b);
    Eigen::VectorXd r = b - matrix * x;
    Eigen::VectorXd z = solver_->solve(r);
    Eigen::VectorXd direction = z;
    double rz = r.dot(z);
    for (int iteration = 0; iteration < kMostSolveIterations; ++iteration) {
      if (r.norm() <= goal) return x;
      const Eigen::VectorXd product = matrix * direction;
      const double curvature = direction.dot(product);
      if (!(curvature > 0)) return std::nullopt;
      const double alpha = rz / curvature;
      x += alpha * direction;
      r -= alpha * product;
      z = solver_->solve(r);
      const double next = r.dot(z);
      direction = z + (next / rz) * direction;
      rz = next;
    }
    if (r.norm() <= goal) return x;
    return std::nullopt;
  }
  void set_weights(const std::vector<FitPair>& pairs, double smooth, double rigid) {
    smooth_ = smooth;
    rigid_ = rigid;
    // The fit as heavy as `fit` for each node, however many pairs there are.
    fit_ = pairs.empty() ? 0 : options_.fit * double(maps_.size()) / double(pairs.size());
  }
  Eigen::Matrix3d fit_weight(const FitPair& pair) const {
    return fit_ * (pair.normal * pair.normal.transpose() + options_.point_to_point * Eigen::Matrix3d::Identity());
  }
  Eigen::Vector3d edge_residual(std::uint32_t j, std::uint32_t k, const std::vector<Affine>& maps) const {
    return maps[j].leftCols<3>() * (node(k) - node(j)) + node(j) + maps[j].col(3) - node(k) - maps[k].col(3);
  }
  double energy(const std::vector<FitPair>& pairs, const std::vector<Affine>& maps) const {
    double sum = 0;
    for (const FitPair& pair : pairs) {
      const Eigen::Vector3d e = moved_vertex(pair.vertex, maps) - pair.target;
      sum += e.dot(fit_weight(pair) * e);
    }
    for (const auto& [a, b] : graph_.edges) {
      sum += smooth_ * (edge_residual(a, b, maps).squaredNorm() + edge_residual(b, a, maps).squaredNorm());
    }
    for (const Affine& m : maps) sum += rigid_ * rotation_residuals(m, nullptr).squaredNorm();
    return sum;
  }

  const DeformationGraph& graph_;
  PointSet points_;
  const DeformationGraphOptions& options_;
  std::vector<Affine> maps_;
  std::unique_ptr<BlockMatrix> hessian_;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper>> solver_;
  double smooth_ = 0, rigid_ = 0, fit_ = 0;
  double factored_smooth_ = 0;  // the stage whose first matrix solver_ holds
};

// Each template vertex to its nearest shape vertex, and each shape vertex to
// its nearest moved template vertex, where their normals agree.
std::vector<FitPair> closest_pairs(const SurfaceMesh& template_mesh, const PointSet& moved, const PointSet& shape,
                                   const PointSet& shape_normals, const MatrixRowTree<PointSet>& shape_tree,
                                   const DeformationGraph& graph, double min_cosine) {
  const PointSet normals = vertex_normals(template_mesh.triangles(), moved);
  const MatrixRowTree<PointSet> template_tree(moved);
  std::vector<FitPair> pairs;
  const auto pair_up = [&](Eigen::Index v, Eigen::Index w) {
    if (graph.influence_offsets[std::size_t(v)] == graph.influence_offsets[std::size_t(v) + 1]) return;
    if (normals.row(v).dot(shape_normals.row(w)) < min_cosine) return;
    pairs.push_back({std::uint32_t(v), shape.row(w).transpose(), shape_normals.row(w).transpose()});
  };
  for (Eigen::Index v = 0; v < moved.rows(); ++v) pair_up(v, Eigen::Index(shape_tree.nearest(moved.row(v)).front()));
  for (Eigen::Index w = 0; w < shape.rows(); ++w) pair_up(Eigen::Index(template_tree.nearest(shape.row(w)).front()), w);
  return pairs;
}

// Each template vertex (with a node) to its guide's shape vertex.
std::vector<FitPair> guided_pairs(const std::vector<Eigen::Index>& guide, const PointSet& shape,
                                  const PointSet& shape_normals, const DeformationGraph& graph) {
  std::vector<FitPair> pairs;
  for (std::size_t v = 0; v < guide.size(); ++v) {
    if (graph.influence_offsets[v] == graph.influence_offsets[v + 1]) continue;
    pairs.push_back({std::uint32_t(v), shape.row(guide[v]).transpose(), shape_normals.row(guide[v]).transpose()});
  }
  return pairs;
}

// The shape's vertex normals, turned round where most of them face against
// the template's at the nearest points (its triangles wound the other way
// round): else every pair would be left out.
PointSet normals_facing_template(const SurfaceMesh& shape_mesh, const PointSet& shape,
                                 const MatrixRowTree<PointSet>& shape_tree, const SurfaceMesh& template_mesh,
                                 const PointSet& template_points) {
  PointSet normals = vertex_normals(shape_mesh.triangles(), shape);
  const PointSet template_normals = vertex_normals(template_mesh.triangles(), template_points);
  std::ptrdiff_t agree = 0;
  for (Eigen::Index v = 0; v < template_points.rows(); ++v) {
    const double cosine = template_normals.row(v).dot(normals.row(shape_tree.nearest(template_points.row(v)).front()));
    agree += cosine > 0 ? 1 : cosine < 0 ? -1 : 0;
  }
  if (agree < 0) normals = -normals;
  return normals;
}

// The rms of each vertex's distance to the other surface, both ways.
double surface_rms(const SurfaceMesh& template_mesh, const PointSet& moved, const SurfaceMesh& shape_mesh,
                   const PointSet& shape_points) {
  const SurfaceMesh moved_mesh(positions_of(moved), template_mesh.triangles());
  const SurfaceMesh shape(positions_of(shape_points), shape_mesh.triangles());
  double sum = 0;
  for (const auto& [from, onto] : {std::pair(&moved_mesh, &shape), std::pair(&shape, &moved_mesh)}) {
    const NearestSurfacePoint nearest(*onto);
    for (const Vec3& p : from->positions()) {
      const double d = distance(nearest.find(p).value().at, p);
      sum += d * d;
    }
  }
  return std::sqrt(sum / double(moved_mesh.vertex_count() + shape.vertex_count()));
}

}  // namespace

DeformationGraphOptions coarse_deformation_graph_options() {
  DeformationGraphOptions options;
  options.vertices_per_node = 100;
  options.min_nodes = 32;
  options.max_nodes = 64;
  options.iterations_per_stage = 4;
  options.smooth_floor = 0.125;
  return options;
}

DeformationGraph build_deformation_graph(const SurfaceMesh& mesh, const DeformationGraphOptions& options) {
  if (options.nodes_per_vertex < 1 || options.nodes_per_vertex > kMostNodesPerVertex) {
    throw std::invalid_argument("deformation graph: nodes_per_vertex " + std::to_string(options.nodes_per_vertex) +
                                " outside 1 to " + std::to_string(kMostNodesPerVertex));
  }
  DeformationGraph graph;
  const std::size_t vertices = mesh.vertex_count();
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  PlacementRequest placement;
  placement.init = Init::farthest;
  placement.particle_count = node_count(vertices, options);
  placement.start_vertex = 0;
  graph.nodes = place_particles(mesh, *solver, placement);
  graph.spacing = std::sqrt(mesh.area() / double(graph.nodes.size()));

  SolverScratch scratch;
  std::vector<double> nearest(vertices);
  solver->solve(graph.nodes, nearest, scratch);
  const double reach = kInfluenceReach * largest_finite(std::vector<float>(nearest.begin(), nearest.end()));
  // Every vertex's nodes within reach, nearest first (ties: the lower node).
  std::vector<std::vector<std::pair<float, std::uint32_t>>> near(vertices);
  for (std::uint32_t j = 0; j < graph.nodes.size(); ++j) {
    const Ball ball = solver->solve_ball(graph.nodes[j], reach, scratch);
    for (std::size_t i = 0; i < ball.vertices.size(); ++i) near[ball.vertices[i]].emplace_back(ball.distances[i], j);
  }
  const std::size_t k = options.nodes_per_vertex;
  graph.influence_offsets.push_back(0);
  std::vector<std::uint32_t> owner(vertices, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t v = 0; v < vertices; ++v) {
    std::vector<std::pair<float, std::uint32_t>>& list = near[v];
    std::sort(list.begin(), list.end());
    if (!list.empty()) owner[v] = list.front().second;
    const std::size_t used = std::min(k, list.size());
    const double farthest = list.size() > k ? double(list[k].first) : reach;
    double total = 0;
    std::vector<double> weights(used);
    for (std::size_t i = 0; i < used; ++i) {
      weights[i] = farthest > 0 ? std::pow(1 - double(list[i].first) / farthest, 2) : 1;
      total += weights[i];
    }
    for (std::size_t i = 0; i < used; ++i) {
      graph.influence_nodes.push_back(list[i].second);
      graph.influence_weights.push_back(total > 0 ? weights[i] / total : 1.0 / double(used));
    }
    graph.influence_offsets.push_back(std::uint32_t(graph.influence_nodes.size()));
  }
  // Nodes whose geodesic Voronoi regions share a mesh edge.
  for (VertexId v = 0; v < vertices; ++v) {
    for (const VertexId w : mesh.one_ring(v)) {
      if (owner[v] < owner[w] && owner[w] != std::numeric_limits<std::uint32_t>::max()) {
        graph.edges.emplace_back(owner[v], owner[w]);
      }
    }
  }
  std::sort(graph.edges.begin(), graph.edges.end());
  graph.edges.erase(std::unique(graph.edges.begin(), graph.edges.end()), graph.edges.end());
  return graph;
}

DeformationGraph template_graph(const SurfaceMesh& template_mesh, const PointSet& template_points,
                                const DeformationGraphOptions& options) {
  return build_deformation_graph(SurfaceMesh(positions_of(template_points), template_mesh.triangles()), options);
}

GraphFit deform_by_graph(const SurfaceMesh& template_mesh, const PointSet& template_points,
                         const SurfaceMesh& shape_mesh, const PointSet& shape_points,
                         const DeformationGraphOptions& options) {
  return deform_by_graph(template_graph(template_mesh, template_points, options), template_mesh, template_points,
                         shape_mesh, shape_points, options);
}

GraphFit deform_by_graph(const DeformationGraph& graph, const SurfaceMesh& template_mesh,
                         const PointSet& template_points, const SurfaceMesh& shape_mesh, const PointSet& shape_points,
                         const DeformationGraphOptions& options, const std::vector<Eigen::Index>* guide) {
  // In node spacings about the template's centroid: the weights mean the
  // same at any scale.
  const Eigen::RowVector3d centre = template_points.colwise().mean();
  const double unit = graph.spacing;
  const PointSet shape = (shape_points.rowwise() - centre) / unit;
  PointSet moved = (template_points.rowwise() - centre) / unit;
  const MatrixRowTree<PointSet> shape_tree(shape);
  const PointSet shape_normals = normals_facing_template(shape_mesh, shape, shape_tree, template_mesh, moved);
  GraphSolve solve(graph, moved, options);
  const double min_cosine = std::cos(options.max_normal_angle_degrees * std::numbers::pi / 180);
  for (double smooth = options.smooth_start; smooth >= options.smooth_floor; smooth /= 2) {
    for (int iteration = 0; iteration < options.iterations_per_stage; ++iteration) {
      const std::vector<FitPair> pairs =
          guide && smooth > options.guided_above
              ? guided_pairs(*guide, shape, shape_normals, graph)
              : closest_pairs(template_mesh, moved, shape, shape_normals, shape_tree, graph, min_cosine);
      const bool stepped = solve.step(pairs, smooth, options.rigid_ratio * smooth);
      PointSet next = solve.moved_points();
      const double largest_move = (next - moved).rowwise().norm().maxCoeff();
      moved = std::move(next);
      if (!stepped || largest_move < options.settled) break;
    }
  }
  GraphFit fit;
  fit.moved = (moved * unit).rowwise() + centre;
  fit.rms = surface_rms(template_mesh, fit.moved, shape_mesh, shape_points);
  fit.nodes = graph.nodes.size();
  return fit;
}

}  // namespace meshparticles
