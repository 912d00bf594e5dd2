// batch(): `meshparticles batch INPUTS --out DIR` in-process - the same
// planning, resume checks and output folders (batch/batch_runner.hpp), one
// process (no MPI ranks here). Returns summary.json's text: meshes that were
// refused or failed are rows of the summary, not exceptions, so one bad
// mesh of a population does not cost the others.
#include <pybind11/stl.h>

#include <fstream>
#include <sstream>

#include "batch/batch_runner.hpp"
#include "bindings.hpp"
#include "cancellation.hpp"
#include "common/user_error.hpp"
#include "run_settings.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

std::string run_batch_json(const py::list& inputs, const py::object& out, const py::kwargs& given) {
  KeywordOptions options(given);
  BatchRequest request;
  for (const py::handle input : inputs) request.inputs.push_back(path_argument(input, "inputs").string());
  request.out = path_argument(out, "out");
  const RunOptionValues run = take_run_options(options);
  request.run = run_request(run);
  const auto n = run.particles;
  const auto spacing = options.take_positive("spacing");
  const auto per_area = options.take_positive("per_area");
  request.read.strict = options.take_flag("strict").value_or(false);
  request.force = options.take_flag("force").value_or(false);
  const CancelScope cancel(options.take_object("cancel"));
  options.refuse_unknown("batch");
  if (int(n.has_value()) + int(spacing.has_value()) + int(per_area.has_value()) > 1) {
    throw UserError("batch: give at most one of n, spacing and per_area");
  }
  request.quiet = request.run.quiet;
  request.count.value = double(request.run.particles);
  if (spacing) request.count = {ParticleCount::Rule::spacing, *spacing};
  if (per_area) request.count = {ParticleCount::Rule::per_area, *per_area};
  {
    py::gil_scoped_release unlocked;  // minutes to hours; Ctrl-C or cancel stops it at a progress update
    run_batch(request);
  }
  std::ifstream summary(request.out / "summary.json");
  std::ostringstream text;
  text << summary.rdbuf();
  return text.str();
}

}  // namespace

void bind_batch(py::module_& module) {
  module.def("batch_json", &run_batch_json, py::arg("inputs"), py::arg("out"));
}

}  // namespace meshparticles::python
