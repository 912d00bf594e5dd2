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
#include "common/user_error.hpp"
#include "run_settings.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

std::string run_batch_json(const std::vector<std::string>& inputs, const std::string& out, const py::kwargs& given) {
  KeywordOptions options(given);
  BatchRequest request;
  request.inputs = inputs;
  request.out = out;
  request.run = take_run_request(options);
  const auto n = options.take_whole("n", kParticleRange);
  const auto spacing = options.take<double>("spacing");
  const auto per_area = options.take<double>("per_area");
  request.read.strict = options.take<bool>("strict").value_or(false);
  request.force = options.take<bool>("force").value_or(false);
  options.refuse_unknown("batch");
  if (int(n.has_value()) + int(spacing.has_value()) + int(per_area.has_value()) > 1) {
    throw UserError("batch: give at most one of n, spacing and per_area");
  }
  for (const auto& [name, value] : {std::pair{"spacing", spacing}, std::pair{"per_area", per_area}}) {
    if (value && !(*value > 0)) throw UserError(std::string(name) + ": expected a number above 0");
  }
  request.quiet = request.run.quiet;
  request.count.value = double(n.value_or(request.run.particles));
  if (spacing) request.count = {ParticleCount::Rule::spacing, *spacing};
  if (per_area) request.count = {ParticleCount::Rule::per_area, *per_area};
  {
    py::gil_scoped_release unlocked;  // minutes to hours; Ctrl-C stops it between progress updates
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
