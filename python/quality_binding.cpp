// quality() and compare(): `meshparticles quality MESH PARTICLES --json` and
// `compare MESH A B --json` on points in memory - the same call
// (pipeline/point_set_measurement.hpp), returned as that JSON's text.
#include <cmath>

#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "cancellation.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"
#include "mesh_object.hpp"
#include "particles/potentials.hpp"
#include "pipeline/point_set_measurement.hpp"
#include "reports/quality_report.hpp"
#include "run_settings.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

// What read_particle_points refuses in a file, refused here in an array.
std::vector<Vec3> points_of(const py::array& array) {
  if (array.ndim() != 2 || array.shape(1) != 3) throw py::value_error("points: expected an array of shape (P, 3)");
  if (array.shape(0) == 0) throw UserError("points: no points");
  const auto points = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!points) throw py::type_error("points: expected a numeric array");
  const auto p = points.unchecked<2>();
  std::vector<Vec3> out;
  for (py::ssize_t i = 0; i < p.shape(0); ++i) {
    const Vec3 point{p(i, 0), p(i, 1), p(i, 2)};
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) {
      throw UserError("points: point " + std::to_string(i) + " is not three finite numbers");
    }
    out.push_back(point);
  }
  return out;
}

// One set (quality) or two (compare), as the commands measure them.
std::string measure(const Mesh& mesh, const std::vector<py::array>& arrays, const py::kwargs& given) {
  KeywordOptions options(given);
  PointSetsRequest request;
  for (const py::array& array : arrays) request.points.push_back(points_of(array));
  request.names = arrays.size() == 2 ? std::vector<std::string>{"<a>", "<b>"} : std::vector<std::string>{"<points>"};
  const RunOptionValues keywords = take_run_options(
      options, {"sigma", "potential", "geodesic", "threads", "quiet", "cache-dir", "no-cache", "distances", "cutoff"});
  const std::string refine = options.take_word("refine").value_or("auto");
  request.sigma = keywords.sigma;
  if (keywords.potential) request.potential = parse_potential(*keywords.potential);
  request.geodesics = geodesics_request(keywords);
  request.distances = distances_request(keywords, request.geodesics);
  const CancelScope cancel(options.take_object("cancel"));
  options.refuse_unknown(arrays.size() == 2 ? "compare" : "quality");
  set_refinement(request, refine);
  py::gil_scoped_release unlocked;
  return json_text(point_sets_json(mesh.label, measure_point_sets(*mesh.surface, request)));
}

}  // namespace

void bind_quality(py::module_& module) {
  module.def(
      "quality_json",
      [](const Mesh& mesh, const py::array& points, const py::kwargs& options) {
        return measure(mesh, {points}, options);
      },
      py::arg("mesh"), py::arg("points"));
  module.def(
      "compare_json",
      [](const Mesh& mesh, const py::array& a, const py::array& b, const py::kwargs& options) {
        return measure(mesh, {a, b}, options);
      },
      py::arg("mesh"), py::arg("a"), py::arg("b"));
}

}  // namespace meshparticles::python
