// geodesics(): what `meshparticles geodesics --source` writes, for several
// sources at once - one row per source, one column per vertex of the input
// (input ids; a vertex the reader dropped is +inf, as one beyond
// max_distance or in another component is).
#include <cmath>

#include <pybind11/numpy.h>

#include "argument_values.hpp"
#include "bindings.hpp"
#include "cancellation.hpp"
#include "common/interruption.hpp"
#include "common/user_error.hpp"
#include "geodesics/geodesic_solver.hpp"
#include "geodesics/solver_factory.hpp"
#include "mesh_object.hpp"
#include "pipeline/mesh_input.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

// Every id first, so that a bad one is refused before any work.
std::vector<VertexId> surface_sources(const SurfaceMesh& surface, const py::iterable& sources) {
  std::vector<VertexId> out;
  for (const py::handle source : sources) {
    const std::uint64_t id = whole_number(source, "sources", kVertexIdRange);
    out.push_back(surface_vertex_for_option(surface, std::size_t(id), "source"));
  }
  return out;
}

// At least 0; inf (the default) is no limit.
double distance_limit(const py::object& max_distance) {
  if (max_distance.is_none()) return kNoDistanceLimit;
  const double limit = real_number(max_distance, "max_distance");
  if (!(limit >= 0)) {
    throw UserError("max_distance: expected a number from 0 up (inf: no limit), got " +
                    py::repr(py::float_(limit)).cast<std::string>());
  }
  return limit;
}

py::array_t<double> distances_from(const Mesh& mesh, const py::iterable& source_ids, const py::object& max_distance,
                                   const py::object& geodesic, const py::object& cancel_event) {
  const SurfaceMesh& surface = *mesh.surface;
  const GeodesicMethod method = parse_method(word(geodesic, "geodesic"));
  const double limit = distance_limit(max_distance);
  const std::vector<VertexId> sources = surface_sources(surface, source_ids);
  const CancelScope cancel(cancel_event.is_none() ? std::nullopt : std::optional<py::object>(cancel_event));
  const std::size_t columns = surface.input_vertex_count();
  py::array_t<double> out({py::ssize_t(sources.size()), py::ssize_t(columns)});
  double* rows = out.mutable_data();
  {
    py::gil_scoped_release unlocked;
    const auto solver = make_geodesic_solver(surface, method);
    SolverScratch scratch;
    std::vector<double> distances(surface.vertex_count());
    for (std::size_t k = 0; k < sources.size(); ++k) {
      throw_if_interrupted();  // Ctrl-C or cancel between sources: no progress line here to ask
      solver->solve(sources[k], distances, scratch, limit);
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
             py::arg("max_distance") = py::none(), py::arg("geodesic") = "fmm", py::arg("cancel") = py::none());
}

}  // namespace meshparticles::python
