#include "geodesics/single_source.hpp"

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

std::unique_ptr<SingleSourceGeodesics> make_geodesics(const SurfaceMesh& mesh, GeodesicMethod method) {
  if (method == GeodesicMethod::dijkstra) return std::make_unique<EdgeDijkstra>(mesh);
  return std::make_unique<FastMarching>(mesh);
}

}  // namespace meshparticles
