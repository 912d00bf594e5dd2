// A full disk for tests, without root or a mount: LD_PRELOAD this library
// with FULL_DISK_DIR=/absolute/dir and FULL_DISK_BYTES=N, and writes to
// files under that directory fail with ENOSPC once N bytes have gone to
// them in this process (the write that crosses the limit is cut short, as on
// a real file system). Other files (stdout, stderr) are untouched.
#include <dlfcn.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// Atomic: a run writes its files from several threads at once.
std::atomic<long long> bytes_written{0};

bool is_under_full_directory(int fd) {
  const char* directory = getenv("FULL_DISK_DIR");
  if (!directory || !*directory) return false;
  char link[64], target[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t length = readlink(link, target, sizeof target - 1);
  if (length < 0) return false;
  target[length] = '\0';
  return strncmp(target, directory, strlen(directory)) == 0;
}

// How many of `wanted` bytes may still be written; 0 means the disk is full.
size_t room_for(int fd, size_t wanted) {
  if (!is_under_full_directory(fd)) return wanted;
  const long long limit = atoll(getenv("FULL_DISK_BYTES") ? getenv("FULL_DISK_BYTES") : "0");
  const long long written = bytes_written;
  const long long left = limit > written ? limit - written : 0;
  return static_cast<long long>(wanted) < left ? wanted : static_cast<size_t>(left);
}

}  // namespace

extern "C" ssize_t write(int fd, const void* buffer, size_t count) {
  using Write = ssize_t (*)(int, const void*, size_t);
  static const auto real_write = reinterpret_cast<Write>(dlsym(RTLD_NEXT, "write"));
  const size_t room = room_for(fd, count);
  if (count > 0 && room == 0) {
    errno = ENOSPC;
    return -1;
  }
  const ssize_t written = real_write(fd, buffer, room);
  if (written > 0 && is_under_full_directory(fd)) bytes_written += written;
  return written;
}

extern "C" ssize_t writev(int fd, const struct iovec* vectors, int count) {
  // Through write(), one piece at a time: the limit holds the same way.
  ssize_t total = 0;
  for (int i = 0; i < count; ++i) {
    const ssize_t written = write(fd, vectors[i].iov_base, vectors[i].iov_len);
    if (written < 0) return total > 0 ? total : -1;
    total += written;
    if (static_cast<size_t>(written) < vectors[i].iov_len) break;
  }
  return total;
}
