// The program's errors as Python exceptions: a UserError (bad input, bad
// options: what the command line prints as one line and exits 2 on) is a
// ValueError with that line; one that means no usable OpenCL runtime or
// device (exit code 3 on the command line) is meshparticles.DeviceError, so
// that a caller can fall back to a serial backend. Ctrl-C stops a long call
// with KeyboardInterrupt, a set cancel event with meshparticles.Cancelled
// (python/cancellation.hpp). Messages are made one line of valid UTF-8: a
// path that is not UTF-8 shows its stray bytes as \xHH.
#include <Python.h>

#include <filesystem>

#include "bindings.hpp"
#include "cancellation.hpp"
#include "common/interruption.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "opencl/device_discovery.hpp"

namespace py = pybind11;

namespace meshparticles::python {

void bind_errors(py::module_& module) {
  // Owned by the module from here on; the translator only borrows it, and a
  // module is never unloaded.
  static PyObject* device_error =
      PyErr_NewExceptionWithDoc("meshparticles._core.DeviceError",
                                "No usable OpenCL runtime or device for what was asked", PyExc_RuntimeError, nullptr);
  module.add_object("DeviceError", py::handle(device_error));
  static PyObject* cancelled = PyErr_NewExceptionWithDoc(
      "meshparticles._core.Cancelled", "A call stopped because its cancel event was set", PyExc_Exception, nullptr);
  module.add_object("Cancelled", py::handle(cancelled));
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const UserError& problem) {
      PyErr_SetString(problem.exit_code() == kNoRuntimeExitCode ? device_error : PyExc_ValueError,
                      one_line(problem.what()).c_str());
    } catch (const Interrupted&) {
      // The check has already set KeyboardInterrupt, Cancelled (or what a handler raised).
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const std::filesystem::filesystem_error& problem) {
      // It quotes paths: pybind11's own translation would fail to decode one
      // that is not UTF-8.
      PyErr_SetString(PyExc_RuntimeError, one_line(problem.what()).c_str());
    }
  });
  // Ctrl-C or a cancel event during a long call: Python's handler only marks
  // the signal; the C++ work asks at its progress updates and unwinds (Interrupted).
  install_interruption_check(cancelled);
}

}  // namespace meshparticles::python
