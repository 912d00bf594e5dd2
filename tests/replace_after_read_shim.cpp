// A file replaced the moment it has been read, for tests: LD_PRELOAD this
// library with REPLACE_AFTER_READ=PATH and REPLACE_WITH=OTHER, and the first
// time the process closes a descriptor open on PATH, OTHER is renamed onto
// PATH (once). Whatever the process reads of PATH after that is OTHER's: a
// program that reads a file twice (to parse it, then to hash it) is caught
// reading two files.
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

namespace {

bool open_on_target(int descriptor) {
  static bool done = false;
  const char* target = getenv("REPLACE_AFTER_READ");
  if (done || !target || !*target) return false;
  char link[64], opened[PATH_MAX], wanted[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", descriptor);
  const ssize_t length = readlink(link, opened, sizeof opened - 1);
  if (length < 0 || !realpath(target, wanted)) return false;
  opened[length] = '\0';
  if (strcmp(opened, wanted) != 0) return false;
  done = true;
  return true;
}

}  // namespace

extern "C" int close(int descriptor) {
  using Close = int (*)(int);
  static const auto real_close = reinterpret_cast<Close>(dlsym(RTLD_NEXT, "close"));
  const bool replace = open_on_target(descriptor);
  const int result = real_close(descriptor);
  if (replace) rename(getenv("REPLACE_WITH"), getenv("REPLACE_AFTER_READ"));
  return result;
}
