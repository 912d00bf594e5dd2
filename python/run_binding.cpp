// run(): `meshparticles run` without its files - plan_run, execute_run, and
// the result kept in memory; Result.save(dir) writes what `run --out dir`
// writes (reports/run_outputs.hpp), by the same code.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "argument_values.hpp"
#include "bindings.hpp"
#include "cancellation.hpp"
#include "common/json_text.hpp"
#include "mesh_object.hpp"
#include "pipeline/run_pipeline.hpp"
#include "reports/file_digest.hpp"
#include "reports/particle_locations.hpp"
#include "reports/quality_report.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"
#include "run_settings.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

struct RunOutput {
  Mesh mesh;
  RunResult result;
  std::optional<std::string> mesh_sha256;  // of the file the mesh was read from
  std::vector<ParticleLocation> locations;  // as particles.particles and particles.csv give them

  nlohmann::json report(const std::filesystem::path& out) const {
    return run_report(*mesh.surface, result, out, mesh_sha256);
  }
};

RunOutput run_mesh(const Mesh& mesh, const py::kwargs& given) {
  KeywordOptions options(given);
  RunRequest request = run_request(take_run_options(options));
  const CancelScope cancel(options.take_object("cancel"));
  options.refuse_unknown("run");
  request.mesh_label = mesh.label;
  RunOutput output{mesh, {}, {}, {}};
  py::gil_scoped_release unlocked;  // minutes on a big mesh; other Python threads go on
  const RunPlan plan = plan_run(*mesh.surface, request);
  output.result = execute_run(*mesh.surface, plan);
  // As `run` does: the digest of the file read, taken after the run.
  if (mesh.file && std::filesystem::is_regular_file(*mesh.file)) output.mesh_sha256 = file_sha256(*mesh.file);
  output.locations = particle_locations(*mesh.surface, output.result);
  return output;
}

void save(const RunOutput& output, const py::object& path) {
  const std::filesystem::path directory = path_argument(path, "directory");
  py::gil_scoped_release unlocked;
  prepare_output_directory(directory);
  write_run_outputs(directory, *output.mesh.surface, output.result, output.report(directory),
                    output.result.plan.request.distances.geodesics.threads);
}

py::array_t<double> positions(const RunOutput& output) {
  py::array_t<double> out({py::ssize_t(output.locations.size()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < output.locations.size(); ++i) {
    const Vec3& at = output.locations[i].at;
    o(i, 0) = at.x, o(i, 1) = at.y, o(i, 2) = at.z;
  }
  return out;
}

// Each particle's input triangle (corner ids, the file's) and barycentric weights.
py::array_t<std::int64_t> triangles(const RunOutput& output) {
  py::array_t<std::int64_t> out({py::ssize_t(output.locations.size()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < output.locations.size(); ++i) {
    for (py::ssize_t k = 0; k < 3; ++k) o(i, k) = output.locations[i].on_input.corners[std::size_t(k)];
  }
  return out;
}

py::array_t<double> weights(const RunOutput& output) {
  py::array_t<double> out({py::ssize_t(output.locations.size()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < output.locations.size(); ++i) {
    for (py::ssize_t k = 0; k < 3; ++k) o(i, k) = output.locations[i].on_input.weights[std::size_t(k)];
  }
  return out;
}

py::array_t<std::int64_t> nearest_vertices(const RunOutput& output) {
  py::array_t<std::int64_t> out(std::vector<py::ssize_t>{py::ssize_t(output.locations.size())});
  auto o = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < output.locations.size(); ++i) o(i) = output.locations[i].input_vertex;
  return out;
}

}  // namespace

void bind_run(py::module_& module) {
  py::class_<RunOutput>(module, "RunOutput")
      .def_property_readonly("positions", &positions)
      .def_property_readonly("vertices", &nearest_vertices)
      .def_property_readonly("triangles", &triangles)
      .def_property_readonly("weights", &weights)
      .def_property_readonly("seconds", [](const RunOutput& output) { return output.result.seconds.total; })
      .def_property_readonly("device", [](const RunOutput& output) { return output.result.device; })
      // JSON text: the package turns it into dicts with json.loads.
      .def("report_json", [](const RunOutput& output) { return json_text(output.report("")); })
      .def("quality_json", [](const RunOutput& output) { return json_text(quality_json(output.result.quality)); })
      // The key of report.json holding the method's record per iteration.
      .def_property_readonly("trace_key",
                             [](const RunOutput& output) { return iteration_records_key(output.result.plan.method); })
      .def("save", &save, py::arg("directory"));
  module.def("run", &run_mesh, py::arg("mesh"));
}

}  // namespace meshparticles::python
