// A kill at a chosen moment of a write, for tests: LD_PRELOAD this library
// with KILL_AT_RENAME=SUFFIX, and the process kills itself with SIGKILL when
// it renames something onto a path ending in SUFFIX (the last step of every
// atomic write: common/atomic_file, common/atomic_directory).
// KILL_AT_RENAME_WHEN=before kills it just before that rename, leaving the
// temporary; anything else kills it just after, leaving the new file and
// nothing written after it. Unlike a kill from outside, it cannot come too
// early or too late. KILL_AT_RENAME_SIGNAL=STOP stops the process there
// instead (SIGSTOP), holding what it holds, until it is sent SIGCONT; it
// stops once, at the first such rename.
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace {

bool ends_with_target(const char* path) {
  const char* suffix = getenv("KILL_AT_RENAME");
  if (!suffix || !*suffix || !path) return false;
  const size_t length = strlen(path), suffix_length = strlen(suffix);
  return length >= suffix_length && strcmp(path + length - suffix_length, suffix) == 0;
}

bool kill_before() {
  const char* when = getenv("KILL_AT_RENAME_WHEN");
  return when && strcmp(when, "before") == 0;
}

// The signal, sent once: the target is forgotten (a file rewritten as
// the work goes on, like batch's summary, does not stop the process again).
void send_signal() {
  const char* name = getenv("KILL_AT_RENAME_SIGNAL");
  const int signal = name && strcmp(name, "STOP") == 0 ? SIGSTOP : SIGKILL;
  unsetenv("KILL_AT_RENAME");
  raise(signal);
}

template <typename Rename>
int renamed(const char* destination, Rename&& rename) {
  const bool target = ends_with_target(destination);
  if (target && kill_before()) send_signal();
  const int result = rename();
  if (target && !kill_before() && result == 0) send_signal();
  return result;
}

}  // namespace

extern "C" int rename(const char* from, const char* to) {
  using Rename = int (*)(const char*, const char*);
  static const auto real_rename = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "rename"));
  return renamed(to, [&] { return real_rename(from, to); });
}

extern "C" int renameat2(int from_directory, const char* from, int to_directory, const char* to, unsigned flags) {
  using Rename = int (*)(int, const char*, int, const char*, unsigned);
  static const auto real_rename = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "renameat2"));
  return renamed(to, [&] { return real_rename(from_directory, from, to_directory, to, flags); });
}
