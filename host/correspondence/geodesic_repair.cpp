#include "correspondence/geodesic_repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "common/median.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

namespace {

// A particle (or anchor) whose distances to the trusted anchors differ from
// the template's by more than this on the median (at unit area) is out of
// place. FAUST's poses, at unit area: bending at the joints changes
// distances by 0.004 to 0.03 (the median anchor's), an arm left on the
// torso by 0.26 to 0.51.
constexpr double kOutOfPlace = 0.04;
// Shapes that are not bent copies of the template (other proportions: FAUST's
// people) keep no distance exactly: out of place is then this many times
// the median anchor's miss.
constexpr double kPastTheUsual = 3;
// A particle moves only where its distances fit this many times better
// there: an arm left on the torso fits 4 to 20 times better on the arm; on
// FAUST's people, where a girth differs, most moves gained under 4 and made
// the map worse (spread 0.30 / 0.43 against 0.36 / 0.53 moving them all).
constexpr double kGain = 4;
constexpr int kRounds = 3;

double distance_at(const std::vector<double>& field, const SurfaceMesh& mesh, const SurfaceLocation& at) {
  const Triangle& corners = mesh.triangles()[at.triangle];
  double sum = 0;
  for (std::size_t k = 0; k < 3; ++k) sum += at.weights[k] * field[corners[k]];
  return sum;
}

// Geodesic distances from a point of the surface to every vertex, at unit area.
std::vector<double> distances_from(const GeodesicSolver& solver, SolverScratch& scratch, const SurfaceMesh& mesh,
                                   const SurfaceLocation& at, double unit) {
  const Triangle& corners = mesh.triangles()[at.triangle];
  std::array<double, 3> starts{};
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 d = mesh.positions()[corners[k]] - at.at;
    starts[k] = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  }
  std::vector<std::pair<VertexId, float>> within;
  solver.solve_ball_from(corners, starts, kNoDistanceLimit, scratch, within);
  std::vector<double> field(mesh.vertex_count(), std::numeric_limits<double>::infinity());
  for (const auto& [v, d] : within) field[v] = double(d) / unit;
  return field;
}

// The vertex a particle sits on (one weight 1), if it sits on one.
std::optional<VertexId> vertex_at(const SurfaceMesh& mesh, const SurfaceLocation& at) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (at.weights[k] == 1.0) return mesh.triangles()[at.triangle][k];
  }
  return std::nullopt;
}

}  // namespace

TemplateGeodesics template_geodesics(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& particles) {
  TemplateGeodesics reference;
  const std::size_t count = particles.size();
  const std::size_t stride = std::max<std::size_t>(1, (count + kMostAnchors - 1) / kMostAnchors);
  for (std::size_t i = 0; i < count; i += stride) reference.anchors.push_back(i);
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  scratch.fit(mesh.vertex_count());
  const double unit = std::sqrt(mesh.area());
  for (const std::size_t a : reference.anchors) {
    const std::vector<double> field = distances_from(*solver, scratch, mesh, particles[a], unit);
    std::vector<double>& row = reference.between.emplace_back(count);
    for (std::size_t i = 0; i < count; ++i) row[i] = distance_at(field, mesh, particles[i]);
  }
  return reference;
}

GeodesicRepair repair_by_geodesics(const TemplateGeodesics& reference, const SurfaceMesh& mesh,
                                   std::vector<SurfaceLocation>& particles) {
  GeodesicRepair repair;
  const std::size_t count = particles.size();
  const std::size_t anchors = reference.anchors.size();
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(mesh, GeodesicMethod::fast_marching);
  SolverScratch scratch;
  scratch.fit(mesh.vertex_count());
  const double unit = std::sqrt(mesh.area());
  const VertexTriangles around = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  std::vector<std::vector<double>> fields(anchors);
  std::vector<char> moved(count, 0), ever_moved(count, 0);
  // How far particle i's distances to the `trusted` anchors are from the
  // template's: the median anchor's miss.
  const auto inconsistency = [&](std::size_t i, const std::vector<char>& trusted) {
    std::vector<double> misses;
    for (std::size_t a = 0; a < anchors; ++a) {
      if (!trusted[a]) continue;
      misses.push_back(std::abs(distance_at(fields[a], mesh, particles[i]) - reference.between[a][i]));
    }
    return median(misses);
  };
  double out_of_place = kOutOfPlace;
  for (int round = 0; round < kRounds; ++round) {
    // Each anchor's distances on the shape, from where it now lies.
    for (std::size_t a = 0; a < anchors; ++a) {
      if (round == 0 || moved[reference.anchors[a]]) {
        fields[a] = distances_from(*solver, scratch, mesh, particles[reference.anchors[a]], unit);
      }
    }
    std::vector<char> trusted(anchors, 1);
    std::vector<double> anchor_misses(anchors);
    for (std::size_t a = 0; a < anchors; ++a) anchor_misses[a] = inconsistency(reference.anchors[a], trusted);
    if (round == 0) out_of_place = std::max(kOutOfPlace, kPastTheUsual * median(anchor_misses));
    for (std::size_t a = 0; a < anchors; ++a) trusted[a] = anchor_misses[a] < out_of_place;
    repair.anchors = std::size_t(std::count(trusted.begin(), trusted.end(), 1));
    if (repair.anchors < 4) break;  // too few to place anything by
    std::fill(moved.begin(), moved.end(), 0);
    std::size_t moved_now = 0;
    std::vector<double> before(count);
    for (std::size_t i = 0; i < count; ++i) before[i] = inconsistency(i, trusted);
    // The particles on each vertex that stay there, or have moved there: no
    // particle is moved onto a vertex that holds another (two that fit one
    // vertex best would end stacked, a hole left where one belongs: FAUST's
    // people at n = 1,024). One out of place holds its vertex only once it
    // is found to stay.
    std::vector<std::uint32_t> occupants(mesh.vertex_count(), 0);
    for (std::size_t i = 0; i < count; ++i) {
      const std::optional<VertexId> v = vertex_at(mesh, particles[i]);
      if (v && before[i] < out_of_place) ++occupants[*v];
    }
    for (std::size_t i = 0; i < count; ++i) {
      if (before[i] < out_of_place) continue;
      // The free vertex whose distances to the trusted anchors fit the template's best.
      const std::optional<VertexId> own = vertex_at(mesh, particles[i]);
      VertexId best = 0;
      double best_cost = std::numeric_limits<double>::infinity();
      for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (occupants[v] > 0) continue;
        double cost = 0;
        for (std::size_t a = 0; a < anchors && cost < best_cost; ++a) {
          if (!trusted[a]) continue;
          const double miss = fields[a][v] - reference.between[a][i];
          cost += miss * miss;
        }
        if (cost < best_cost) {
          best_cost = cost;
          best = v;
        }
      }
      std::vector<double> misses_there;
      for (std::size_t a = 0; a < anchors; ++a) {
        if (trusted[a]) misses_there.push_back(std::abs(fields[a][best] - reference.between[a][i]));
      }
      if (!(best_cost < std::numeric_limits<double>::infinity()) || !(median(misses_there) * kGain < before[i])) {
        if (own) ++occupants[*own];
        continue;
      }
      ++occupants[best];
      SurfaceLocation& at = particles[i];
      at.triangle = around.around(best).front();
      const Triangle& corners = mesh.triangles()[at.triangle];
      for (std::size_t k = 0; k < 3; ++k) at.weights[k] = corners[k] == best ? 1.0 : 0.0;
      at.at = mesh.positions()[best];
      moved[i] = ever_moved[i] = 1;
      ++moved_now;
    }
    if (moved_now == 0) break;
  }
  // Every anchor's field was computed in the first round.
  const std::vector<char> every(anchors, 1);
  std::vector<double> after;
  for (std::size_t i = 0; i < count; ++i) after.push_back(inconsistency(i, every));
  repair.inconsistency = median(after);
  repair.moved = std::size_t(std::count(ever_moved.begin(), ever_moved.end(), 1));
  return repair;
}

}  // namespace meshparticles
