// quality(): `meshparticles quality MESH PARTICLES --json` on points in
// memory - the same measuring mesh, distances and metrics
// (quality/particle_sets.hpp), returned as that JSON's text.
#include <cmath>

#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "common/user_error.hpp"
#include "mesh_object.hpp"
#include "pipeline/sigma_check.hpp"
#include "quality/particle_sets.hpp"
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

// The command's --refine: auto, spread, or 0 to 8 uniform rounds.
std::optional<unsigned> uniform_levels(const std::string& refine) {
  if (refine == "auto" || refine == "spread") return std::nullopt;
  if (refine.size() == 1 && refine[0] >= '0' && refine[0] <= '8') return unsigned(refine[0] - '0');
  throw UserError("refine: expected auto, spread or 0 to 8, got '" + refine + "'");
}

std::string measure(const Mesh& mesh, const py::array& points_array, const py::kwargs& given) {
  KeywordOptions options(given);
  const std::vector<Vec3> points = points_of(points_array);
  const auto sigma = options.take<double>("sigma");
  const Potential potential = parse_potential(options.take<std::string>("potential").value_or("exp"));
  const std::string refine = options.take<std::string>("refine").value_or("auto");
  const GeodesicsRequest geodesics = take_geodesics_request(options);
  const DistancesRequest request = take_distances_request(options, geodesics);
  options.refuse_unknown("quality");
  const std::optional<unsigned> levels = uniform_levels(refine);
  if (sigma) {
    if (!(*sigma > 0)) throw UserError("sigma must be a positive number");
    check_sigma_computable({potential, *sigma});
  }
  py::gil_scoped_release unlocked;
  const std::vector<std::vector<Vec3>> sets = {points};
  const MeasuringMesh measuring = measuring_mesh(*mesh.surface, sets, levels, refine == "spread");
  const SurfaceMesh& measured = measuring.refined.mesh;
  const ObtainedDistances obtained = obtain_distances(
      measured, geodesics, plan_distances(measured, request, std::min(points.size(), measured.vertex_count()), false));
  const MeasuredSet set = measure_particle_file(measured, *obtained.store, geodesics.method, "<points>", points,
                                                potential, sigma, geodesics.quiet);
  nlohmann::json out = {{"mesh", mesh.label},
                        {"refinement", measuring.spread ? "spread" : "uniform"},
                        {"refinement_levels", measuring.refined.levels},
                        {"measured_vertices", measured.vertex_count()}};
  out.update(measured_set_json(set));
  return out.dump();
}

}  // namespace

void bind_quality(py::module_& module) {
  module.def("quality_json", &measure, py::arg("mesh"), py::arg("points"));
}

}  // namespace meshparticles::python
