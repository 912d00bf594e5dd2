#include "cancellation.hpp"

#include "common/interruption.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

PyObject* cancelled_error = nullptr;  // meshparticles.Cancelled, owned by the module
// The innermost scope's event on this thread: the check runs on the thread
// that called the work, so each thread's call sees its own event.
thread_local PyObject* current_event = nullptr;

// True with a Python exception set: KeyboardInterrupt (or what a signal
// handler raised), Cancelled, or what the event's is_set() raised.
bool stop_requested() {
  py::gil_scoped_acquire held;
  if (PyErr_CheckSignals() != 0) return true;
  if (!current_event) return false;
  const auto set = py::reinterpret_steal<py::object>(PyObject_CallMethod(current_event, "is_set", nullptr));
  if (!set) return true;
  const int truth = PyObject_IsTrue(set.ptr());
  if (truth < 0) return true;
  if (truth == 0) return false;
  PyErr_SetString(cancelled_error, "cancelled: the cancel event was set");
  return true;
}

}  // namespace

CancelScope::CancelScope(std::optional<py::object> event) : outer_(current_event) {
  if (!event) return;
  if (!py::hasattr(*event, "is_set")) {
    throw py::type_error(std::string("cancel: expected a threading.Event (an object with is_set()), got ") +
                         Py_TYPE(event->ptr())->tp_name);
  }
  event_ = std::move(*event);
  current_event = event_.ptr();
}

CancelScope::~CancelScope() { current_event = outer_; }

void install_interruption_check(PyObject* cancelled) {
  cancelled_error = cancelled;
  set_interruption_check(&stop_requested);
}

}  // namespace meshparticles::python
