#include "geodesics/geodesic_solver.hpp"

#include "common/user_error.hpp"
#include "geodesics/dijkstra.hpp"
#include "geodesics/fast_marching.hpp"

namespace meshparticles {

std::string method_name(GeodesicMethod method) {
  return method == GeodesicMethod::fast_marching ? "fmm" : "dijkstra";
}

GeodesicMethod parse_method(const std::string& name) {
  if (name == "fmm") return GeodesicMethod::fast_marching;
  if (name == "dijkstra") return GeodesicMethod::dijkstra;
  throw UserError("unknown geodesic method '" + name + "' (use fmm or dijkstra)");
}

std::vector<float> ring_edge_lengths(const SurfaceMesh& mesh) {
  std::vector<float> lengths(mesh.ring_neighbors().size());
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    for (std::uint32_t k = mesh.ring_offsets()[v]; k < mesh.ring_offsets()[v + 1]; ++k) {
      lengths[k] = float(distance(mesh.positions()[v], mesh.positions()[mesh.ring_neighbors()[k]]));
    }
  }
  return lengths;
}

std::unique_ptr<GeodesicSolver> make_geodesic_solver(const SurfaceMesh& mesh, GeodesicMethod method) {
  if (method == GeodesicMethod::dijkstra) return std::make_unique<EdgeDijkstra>(mesh);
  return std::make_unique<FastMarching>(mesh);
}

}  // namespace meshparticles
