#include "mesh/mesh_generator.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>

#include "common/random.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using WorkMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using Projection = std::function<Vec3(Vec3)>;
constexpr double kPi = std::numbers::pi;

Vec3 to_vec(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
OpenMesh::Vec3d to_point(const Vec3& p) { return {p.x, p.y, p.z}; }

// Icosahedron with each face cut into frequency^2 triangles, on the unit sphere.
WorkMesh geodesic_sphere(int frequency) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  const std::vector<Vec3> corners = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                     {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  WorkMesh mesh;
  // Points on shared edges are created once: keyed by their exact lattice
  // coordinates (which corner pairs, which fraction), not by rounded floats.
  std::map<std::tuple<int, int, int, int, int, int>, WorkMesh::VertexHandle> lattice;
  const auto point_at = [&](const int face[3], int i, int j) -> WorkMesh::VertexHandle {
    const int k = frequency - i - j;
    std::array<std::pair<int, int>, 3> weights = {{{face[0], i}, {face[1], j}, {face[2], k}}};
    for (auto& [corner, weight] : weights) {
      if (weight == 0) corner = -1;  // a corner with no weight must not distinguish the point
    }
    std::sort(weights.begin(), weights.end());
    const auto key = std::make_tuple(weights[0].first, weights[0].second, weights[1].first, weights[1].second,
                                     weights[2].first, weights[2].second);
    if (auto it = lattice.find(key); it != lattice.end()) return it->second;
    Vec3 p{};
    for (const auto& [corner, weight] : weights) {
      if (weight > 0) p = p + double(weight) * corners[corner];
    }
    const WorkMesh::VertexHandle handle = mesh.add_vertex(to_point(normalized(p)));
    lattice.emplace(key, handle);
    return handle;
  };
  // point_at adds the vertices it has not seen, so the order of the calls
  // numbers them. They are made one statement each, last corner first (the
  // order GCC evaluated them in as arguments, which the committed meshes
  // keep): arguments' order is the compiler's choice, and clang's differs.
  const auto add_triangle = [&](const int face[3], std::array<std::pair<int, int>, 3> at) {
    const WorkMesh::VertexHandle c = point_at(face, at[2].first, at[2].second);
    const WorkMesh::VertexHandle b = point_at(face, at[1].first, at[1].second);
    const WorkMesh::VertexHandle a = point_at(face, at[0].first, at[0].second);
    mesh.add_face(a, b, c);
  };
  for (const auto& face : faces) {
    for (int i = 0; i < frequency; ++i) {
      for (int j = 0; i + j < frequency; ++j) {
        add_triangle(face, {{{i, j}, {i + 1, j}, {i, j + 1}}});
        if (i + j + 2 <= frequency) add_triangle(face, {{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}});
      }
    }
  }
  return mesh;
}

// Splits the longest edge (midpoint projected onto the surface) until the
// mesh has `target` vertices: refines where the base mesh was stretched.
void split_longest_edges(WorkMesh& mesh, std::size_t target, const Projection& project) {
  while (mesh.n_vertices() < target) {
    WorkMesh::EdgeHandle longest;
    double longest_length = -1;
    for (auto e : mesh.edges()) {
      if (mesh.is_boundary(e)) continue;
      const double length = mesh.calc_edge_length(e);
      if (length > longest_length) {
        longest_length = length;
        longest = e;
      }
    }
    const auto h = mesh.halfedge_handle(longest, 0);
    const Vec3 middle = 0.5 * (to_vec(mesh.point(mesh.from_vertex_handle(h))) + to_vec(mesh.point(mesh.to_vertex_handle(h))));
    mesh.split(longest, to_point(project(middle)));
  }
}

double angle_at(const Vec3& corner, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - corner, v = b - corner;
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

// Flips interior edges whose opposite angles sum past pi (the Delaunay
// criterion) unless the flip would fold the surface. Returns the flip count.
std::size_t delaunay_flips(WorkMesh& mesh) {
  std::size_t flips = 0;
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e) || !mesh.is_flip_ok(e)) continue;
    const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
    const Vec3 a = to_vec(mesh.point(mesh.to_vertex_handle(h0)));
    const Vec3 b = to_vec(mesh.point(mesh.to_vertex_handle(h1)));
    const Vec3 c = to_vec(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h0))));
    const Vec3 d = to_vec(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1))));
    if (angle_at(c, a, b) + angle_at(d, a, b) <= kPi + 1e-9) continue;
    // Old triangles (b,a,c) and (a,b,d); new ones (c,d,a)... keep the orientation consistent.
    const Vec3 old_normal = cross(a - b, c - b) + cross(b - a, d - a);
    if (dot(cross(d - c, a - c), old_normal) <= 0 || dot(cross(c - d, b - d), old_normal) <= 0) continue;
    mesh.flip(e);
    ++flips;
  }
  return flips;
}

// Jacobi steps towards the neighbour centroid, projected back onto the surface.
void smooth(WorkMesh& mesh, int steps, const Projection& project) {
  std::vector<Vec3> next(mesh.n_vertices());
  for (int step = 0; step < steps; ++step) {
    for (auto v : mesh.vertices()) {
      const Vec3 p = to_vec(mesh.point(v));
      if (mesh.is_boundary(v)) {
        next[v.idx()] = p;
        continue;
      }
      Vec3 centroid{};
      int count = 0;
      for (auto n : mesh.vv_range(v)) {
        centroid = centroid + to_vec(mesh.point(n));
        ++count;
      }
      next[v.idx()] = project(0.5 * p + (0.5 / count) * centroid);
    }
    for (auto v : mesh.vertices()) mesh.point(v) = to_point(next[v.idx()]);
  }
}

// Moves every interior vertex by a random offset of up to `fraction` of the
// mean edge length, projected back: breaks the base mesh's regular pattern so
// that the flips below leave irregular valences, as a mesher's output has.
void jitter(WorkMesh& mesh, double fraction, const Projection& project, SplitMix64& random) {
  double length_sum = 0;
  for (auto e : mesh.edges()) length_sum += mesh.calc_edge_length(e);
  const double amplitude = fraction * length_sum / double(mesh.n_edges());
  for (auto v : mesh.vertices()) {
    const Vec3 offset{random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5};
    if (!mesh.is_boundary(v)) mesh.point(v) = to_point(project(to_vec(mesh.point(v)) + (2 * amplitude) * offset));
  }
}

void improve(WorkMesh& mesh, const Projection& project) {
  SplitMix64 random(20261120);
  jitter(mesh, 0.5, project, random);
  for (int round = 0; round < 3; ++round) {
    for (int pass = 0; pass < 20 && delaunay_flips(mesh) > 0; ++pass) {
    }
    smooth(mesh, 2, project);
  }
  for (int pass = 0; pass < 20 && delaunay_flips(mesh) > 0; ++pass) {
  }
}

// Numbers vertices breadth-first from vertex 0 so that neighbours have
// nearby ids: refinement appends its vertices at the end, and every later
// stage (fast marching, the particle kernels) reads per-vertex arrays in
// neighbourhood order.
SurfaceMesh to_surface_mesh(const WorkMesh& mesh) {
  const std::size_t n = mesh.n_vertices();
  std::vector<int> new_id(n, -1);
  std::vector<WorkMesh::VertexHandle> order;
  for (std::size_t start = 0; start < n; ++start) {  // every component
    if (new_id[start] >= 0) continue;
    new_id[start] = int(order.size());
    order.push_back(mesh.vertex_handle(unsigned(start)));
    for (std::size_t head = order.size() - 1; head < order.size(); ++head) {
      for (auto neighbor : mesh.vv_range(order[head])) {
        if (new_id[neighbor.idx()] >= 0) continue;
        new_id[neighbor.idx()] = int(order.size());
        order.push_back(neighbor);
      }
    }
  }
  std::vector<Vec3> positions;
  for (auto v : order) positions.push_back(to_vec(mesh.point(v)));
  std::vector<Triangle> triangles;
  for (auto f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : mesh.fv_range(f)) t[k++] = VertexId(new_id[v.idx()]);
    triangles.push_back(t);
  }
  return SurfaceMesh(std::move(positions), std::move(triangles));
}


SurfaceMesh torus() {
  constexpr double R = 1.0, r = 0.4;
  constexpr int around = 48, across = 28;  // 1,344 vertices, refined to 1,500
  const Projection onto_torus = [](Vec3 p) {
    const double rho = std::hypot(p.x, p.y);
    const Vec3 tube_center{R * p.x / rho, R * p.y / rho, 0.0};
    return tube_center + r * normalized(p - tube_center);
  };
  WorkMesh mesh;
  std::vector<WorkMesh::VertexHandle> grid;
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      const double u = 2 * kPi * i / around, v = 2 * kPi * j / across;
      grid.push_back(mesh.add_vertex({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)}));
    }
  }
  const auto at = [&](int i, int j) { return grid[(i % around) * across + (j % across)]; };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  split_longest_edges(mesh, 1500, onto_torus);
  improve(mesh, onto_torus);
  return to_surface_mesh(mesh);
}

// A closed, star-shaped, organ-like surface: an ellipsoid body with bulges.
struct Bulge {
  Vec3 direction;
  double height, width;
};
struct AtriumShape {
  Vec3 axes;  // of the ellipsoid body
  std::vector<Bulge> bulges;
};

// The committed atrium, standing in for the paper's left-atrium mesh: bulges
// of different sizes (an appendage, four vein stubs, one broad bump).
const AtriumShape kAtrium = {{1.25, 1.0, 0.85},
                             {
                                 {normalized({0.3, 0.8, 0.5}), 0.45, 0.05},  // appendage
                                 {normalized({-0.6, 0.5, 0.6}), 0.3, 0.015},  // vein stubs
                                 {normalized({-0.6, -0.5, 0.6}), 0.3, 0.015},
                                 {normalized({-0.7, 0.55, -0.45}), 0.25, 0.015},
                                 {normalized({-0.7, -0.55, -0.45}), 0.25, 0.015},
                                 {normalized({0.8, -0.3, -0.5}), 0.15, 0.25},  // broad bump
                             }};

Projection onto_atrium(const AtriumShape& shape = kAtrium) {
  return [shape](Vec3 p) {
    const Vec3 d = normalized(p);
    const Vec3& a = shape.axes;
    double radius = 1.0 / std::sqrt(d.x * d.x / (a.x * a.x) + d.y * d.y / (a.y * a.y) + d.z * d.z / (a.z * a.z));
    for (const Bulge& b : shape.bulges) radius += b.height * std::exp(-(1.0 - dot(d, b.direction)) / b.width);
    return radius * d;
  };
}

Projection onto_sphere() {
  return [](Vec3 p) { return normalized(p); };
}

// The geodesic sphere of `frequency` on `shape` (nothing to project for the
// sphere itself: projecting again would change the committed file's last
// digits), refined to `target` vertices (none when 0) and improved.
SurfaceMesh sphere_like(int frequency, const Projection& shape, std::size_t target, bool on_sphere) {
  WorkMesh mesh = geodesic_sphere(frequency);
  if (!on_sphere) {
    for (auto v : mesh.vertices()) mesh.point(v) = to_point(shape(to_vec(mesh.point(v))));
  }
  if (target > 0) split_longest_edges(mesh, target, shape);
  improve(mesh, shape);
  return to_surface_mesh(mesh);
}

SurfaceMesh atrium() {
  return sphere_like(29, onto_atrium(), 10500, false);  // 8,412 vertices, refined to 10,500
}

SurfaceMesh sphere() {
  return sphere_like(19, onto_sphere(), 4000, true);  // 3,612 vertices, refined to the paper's ~4k
}

// An open, flat, jittered 20 x 20 grid on [0,1]^2: a boundary, and a plane
// where geodesic distance is Euclidean distance.
SurfaceMesh patch() {
  constexpr int n = 20;
  SplitMix64 random(20261120);
  WorkMesh mesh;
  std::vector<WorkMesh::VertexHandle> grid;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const bool inner = i > 0 && j > 0 && i < n - 1 && j < n - 1;
      const double jitter_x = inner ? 0.35 * (random.uniform() - 0.5) : 0.0;
      const double jitter_y = inner ? 0.35 * (random.uniform() - 0.5) : 0.0;
      grid.push_back(mesh.add_vertex({(i + jitter_x) / (n - 1), (j + jitter_y) / (n - 1), 0.0}));
    }
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const auto a = grid[i * n + j], b = grid[(i + 1) * n + j], c = grid[(i + 1) * n + j + 1], d = grid[i * n + j + 1];
      mesh.add_face(a, b, c);
      mesh.add_face(a, c, d);
    }
  }
  improve(mesh, [](Vec3 p) { return Vec3{p.x, p.y, 0.0}; });
  return to_surface_mesh(mesh);
}

SurfaceMesh tetrahedron() {
  return SurfaceMesh({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

SurfaceMesh two_pieces() {
  const SurfaceMesh first = tetrahedron();
  std::vector<Vec3> positions = first.positions();
  std::vector<Triangle> triangles = first.triangles();
  for (const Vec3& p : first.positions()) positions.push_back(p + Vec3{4, 0, 0});
  for (const Triangle& t : first.triangles()) triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

// A bipyramid over a 24-gon: both apexes have valence 24.
SurfaceMesh high_valence() {
  constexpr int sides = 24;
  std::vector<Vec3> positions = {{0, 0, 1}, {0, 0, -1}};
  std::vector<Triangle> triangles;
  for (int k = 0; k < sides; ++k) {
    positions.push_back({std::cos(2 * kPi * k / sides), std::sin(2 * kPi * k / sides), 0});
    const VertexId here = 2 + k, next = 2 + (k + 1) % sides;
    triangles.push_back({0, here, next});
    triangles.push_back({1, next, here});
  }
  return SurfaceMesh(std::move(positions), std::move(triangles));
}

const std::map<std::string, std::function<SurfaceMesh()>>& generators() {
  static const std::map<std::string, std::function<SurfaceMesh()>> table = {
      {"sphere", sphere},           {"torus", torus},           {"atrium", atrium},
      {"patch", patch},             {"tetrahedron", tetrahedron}, {"two_pieces", two_pieces},
      {"high_valence", high_valence}};
  return table;
}

// The frequency f whose geodesic sphere (10 f^2 + 2 vertices) comes nearest
// to `vertices`. Throws UserError under 12.
int frequency_for(std::size_t vertices) {
  if (vertices < 12) throw UserError("--vertices " + std::to_string(vertices) + ": a sphere needs at least 12");
  return std::max(1, int(std::lround(std::sqrt(double(vertices - 2) / 10.0))));
}

}  // namespace

const std::vector<std::string>& generated_mesh_names() {
  static const std::vector<std::string> names = {"sphere", "torus", "atrium", "patch", "tetrahedron",
                                                 "two_pieces", "high_valence"};
  return names;
}

SurfaceMesh generate_mesh(const std::string& name) {
  const auto it = generators().find(name);
  if (it == generators().end()) throw UserError("unknown mesh '" + name + "' to generate");
  return it->second();
}

const std::vector<std::string>& scalable_mesh_names() {
  static const std::vector<std::string> names = {"sphere", "atrium"};
  return names;
}

SurfaceMesh generate_mesh_at(const std::string& name, std::size_t vertices) {
  if (name != "sphere" && name != "atrium") {
    throw UserError("--vertices applies to sphere and atrium, not " + name);
  }
  const int frequency = frequency_for(vertices);
  return name == "sphere" ? sphere_like(frequency, onto_sphere(), 0, true)
                          : sphere_like(frequency, onto_atrium(), 0, false);
}

SurfaceMesh generate_atrium_variant(std::uint64_t seed, std::size_t vertices) {
  SplitMix64 random(seed);
  const auto around = [&random](double value, double spread) {
    return value * (1.0 + spread * (2 * random.uniform() - 1));
  };
  // The whole shape scaled too: a population's areas differ, as patients' do.
  const double scale = around(1.0, 0.2);
  AtriumShape shape{
      scale * Vec3{around(kAtrium.axes.x, 0.15), around(kAtrium.axes.y, 0.15), around(kAtrium.axes.z, 0.15)}, {}};
  for (const Bulge& bulge : kAtrium.bulges) {
    const Vec3 tilt{around(0.15, 1.0), around(0.15, 1.0), around(0.15, 1.0)};
    shape.bulges.push_back(
        {normalized(bulge.direction + tilt), scale * around(bulge.height, 0.4), around(bulge.width, 0.3)});
  }
  return sphere_like(frequency_for(vertices), onto_atrium(shape), 0, false);
}

}  // namespace meshparticles

namespace meshparticles {

const EllipsoidBump kEllipsoidBump = {normalized({1.0, 0.5, 0.7}), 0.08, 0};
const EllipsoidBump kEllipsoidKnob = {normalized({-0.4, 0.8, -0.45}), 0.04, 0.25};

namespace {

// A rotation drawn uniformly (Shoemake's unit quaternion), as its rows.
std::array<Vec3, 3> random_rotation(SplitMix64& random) {
  const double u1 = random.uniform(), u2 = 2 * kPi * random.uniform(), u3 = 2 * kPi * random.uniform();
  const double w = std::sqrt(1 - u1) * std::sin(u2), x = std::sqrt(1 - u1) * std::cos(u2);
  const double y = std::sqrt(u1) * std::sin(u3), z = std::sqrt(u1) * std::cos(u3);
  return {Vec3{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          Vec3{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          Vec3{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

Vec3 rotate(const std::array<Vec3, 3>& rows, Vec3 p) { return {dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)}; }

}  // namespace

EllipsoidVariant generate_ellipsoid_variant(std::uint64_t seed, std::size_t vertices, EllipsoidFamily family) {
  SplitMix64 random(seed);
  double elongation = 0, height = 0, knob_height = kEllipsoidKnob.height;
  Vec3 axes{};
  if (family == EllipsoidFamily::knob) {
    elongation = 0.2 * (2 * random.uniform() - 1);
    height = 0.35 + 0.25 * (2 * random.uniform() - 1);
    // Three unequal axes whatever the elongation, and a bump off every plane of
    // symmetry: no turn or mirror of a shape fits it, so its correspondence is
    // fixed by its geometry.
    axes = {1.5 * (1 + elongation), 1.0, 0.7 / (1 + elongation)};
  } else {
    // Each radius within 20% of 1.25, 1 and 0.8: their order swaps from shape
    // to shape, so the principal axes' order says nothing. The bump and the
    // knob each of their own height, the knob at times next to none: a
    // shape may be all but symmetric.
    axes = {1.25 * (0.8 + 0.4 * random.uniform()), 0.8 + 0.4 * random.uniform(), 0.8 * (0.8 + 0.4 * random.uniform())};
    height = 0.1 + 0.5 * random.uniform();
    knob_height = 0.3 * random.uniform();
  }
  // Any point maps to the surface point of its parameter, so the mesher's
  // projections keep every vertex on the shape and its parameter exact.
  const Projection onto_shape = [axes, height, knob_height](Vec3 p) {
    const Vec3 u = normalized({p.x / axes.x, p.y / axes.y, p.z / axes.z});
    const double r = 1 + height * std::exp(-(1 - dot(u, kEllipsoidBump.direction)) / kEllipsoidBump.width) +
                     knob_height * std::exp(-(1 - dot(u, kEllipsoidKnob.direction)) / kEllipsoidKnob.width);
    return r * Vec3{axes.x * u.x, axes.y * u.y, axes.z * u.z};
  };
  PosedShape shape = mesh_and_pose_shape(random, vertices, onto_shape, onto_shape);
  return {std::move(shape.mesh), elongation, height, knob_height, axes, shape.pose};
}

PosedShape mesh_and_pose_shape(SplitMix64& random, std::size_t vertices, const std::function<Vec3(Vec3)>& place,
                               const std::function<Vec3(Vec3)>& project) {
  const int frequency = std::max(2, frequency_for(vertices) + int(random.below(3)) - 1);
  const std::array<Vec3, 3> meshing_turn = random_rotation(random);
  WorkMesh mesh = geodesic_sphere(frequency);
  for (auto v : mesh.vertices()) mesh.point(v) = to_point(place(rotate(meshing_turn, to_vec(mesh.point(v)))));
  improve(mesh, project);
  const SurfaceMesh unposed = to_surface_mesh(mesh);

  const std::array<Vec3, 3> rotation = random_rotation(random);
  const double scale = std::exp(std::log(0.5) + std::log(4.0) * random.uniform());  // 0.5 to 2
  const Vec3 translation{10 * random.uniform() - 5, 10 * random.uniform() - 5, 10 * random.uniform() - 5};
  std::vector<Vec3> posed;
  for (const Vec3& p : unposed.positions()) posed.push_back(scale * rotate(rotation, p) + translation);
  return {SurfaceMesh(std::move(posed), unposed.triangles()), {rotation, scale, translation}};
}

}  // namespace meshparticles
