#pragma once
// Long work stopped from outside: a caller (the Python module, for Ctrl-C)
// installs a check, and every progress update asks it, at most every 100 ms.
// When it says stop, the work throws Interrupted from the thread that
// reports progress; loops that run worker threads stop and join them first.
// Nothing is written half: outputs and caches are written atomically after
// the work.
#include <exception>

namespace meshparticles {

class Interrupted : public std::exception {
 public:
  const char* what() const noexcept override { return "interrupted"; }
};

// True when the work should stop. Called from the thread reporting progress.
using InterruptionCheck = bool (*)();

// Installs `check` for the whole process (nullptr: none, the default); it is
// asked at the next progress update.
void set_interruption_check(InterruptionCheck check);

// Throws Interrupted when the check says so; a no-op without a check, and
// the check itself is asked at most every 100 ms on each thread.
void throw_if_interrupted();

}  // namespace meshparticles
