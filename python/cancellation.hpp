#pragma once
// Stopping a long call before it ends. Ctrl-C works on the main thread only
// (Python delivers signals there); from any thread, a call given
// cancel=threading.Event() stops once another thread sets the event, raising
// meshparticles.Cancelled. Both are asked at the work's progress updates,
// through the library's interruption check (common/interruption.hpp), which
// the work asks on the thread that called it.
#include <optional>

#include <pybind11/pybind11.h>

namespace meshparticles::python {

// While it lives, the calling thread's work also stops when `event.is_set()`.
// Made with the GIL held, before the call releases it.
class CancelScope {
 public:
  // `event`: absent, or an object with is_set() (threading.Event,
  // multiprocessing.Event); anything else is a TypeError naming `cancel`.
  explicit CancelScope(std::optional<pybind11::object> event);
  ~CancelScope();
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  pybind11::object event_;
  PyObject* outer_;  // the enclosing scope's event on this thread, if any
};

// Installs the process's interruption check: pending signals (main thread)
// and the calling thread's cancel event; a set event raises `cancelled`.
void install_interruption_check(PyObject* cancelled);

}  // namespace meshparticles::python
