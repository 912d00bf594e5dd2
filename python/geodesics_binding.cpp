// geodesics(): what `meshparticles geodesics --source` writes, for several
// sources at once - one row per source, one column per vertex of the input
// (input ids; a vertex the reader dropped is +inf, as one beyond
// max_distance or in another component is).
#include <cmath>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "mesh_object.hpp"
#include "pipeline/mesh_input.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

py::array_t<double> distances_from(const Mesh& mesh, const std::vector<long long>& sources,
                                   std::optional<double> max_distance, const std::string& geodesic) {
  const SurfaceMesh& surface = *mesh.surface;
  const GeodesicMethod method = parse_method(geodesic);
  if (max_distance && std::isnan(*max_distance)) throw py::value_error("max_distance must be a number");
  std::vector<VertexId> surface_sources;
  for (const long long source : sources) {
    if (source < 0) throw py::value_error("sources: vertex ids must not be negative, got " + std::to_string(source));
    surface_sources.push_back(surface_vertex_for_option(surface, std::size_t(source), "source"));
  }
  const std::size_t columns = surface.input_vertex_count();
  py::array_t<double> out({py::ssize_t(sources.size()), py::ssize_t(columns)});
  double* rows = out.mutable_data();
  {
    py::gil_scoped_release unlocked;
    const auto solver = make_geodesic_solver(surface, method);
    SolverScratch scratch;
    std::vector<double> distances(surface.vertex_count());
    for (std::size_t k = 0; k < surface_sources.size(); ++k) {
      solver->solve(surface_sources[k], distances, scratch, max_distance.value_or(kNoDistanceLimit));
      double* row = rows + k * columns;
      std::fill(row, row + columns, INFINITY);
      for (std::size_t v = 0; v < surface.vertex_count(); ++v) row[surface.input_id(VertexId(v))] = distances[v];
    }
  }
  return out;
}

}  // namespace

void bind_geodesics(py::module_& module) {
  module.def("geodesics", &distances_from, py::arg("mesh"), py::arg("sources"), py::kw_only(),
             py::arg("max_distance") = py::none(), py::arg("geodesic") = "fmm");
}

}  // namespace meshparticles::python
