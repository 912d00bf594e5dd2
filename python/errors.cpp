// The program's errors as Python exceptions: a UserError (bad input, bad
// options: what the command line prints as one line and exits 2 on) is a
// ValueError with that line; one that means no usable OpenCL runtime or
// device (exit code 3 on the command line) is meshparticles.DeviceError, so
// that a caller can fall back to a serial backend. Ctrl-C stops a long call
// with KeyboardInterrupt.
#include <Python.h>

#include "bindings.hpp"
#include "common/interruption.hpp"
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
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const UserError& problem) {
      PyErr_SetString(problem.exit_code() == kNoRuntimeExitCode ? device_error : PyExc_ValueError, problem.what());
    } catch (const Interrupted&) {
      // The check below has already set KeyboardInterrupt (or what a handler raised).
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  // Ctrl-C during a long call: Python's handler only marks the signal; the
  // C++ work asks here at its progress updates and unwinds (Interrupted).
  set_interruption_check([] {
    py::gil_scoped_acquire held;
    return PyErr_CheckSignals() != 0;
  });
}

}  // namespace meshparticles::python
