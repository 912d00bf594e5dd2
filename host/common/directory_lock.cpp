#include "common/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/atomic_file.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

DirectoryLock::DirectoryLock(const std::filesystem::path& directory, const std::string& command)
    : directory_(directory) {
  std::error_code ignored;
  created_ = !std::filesystem::exists(directory, ignored);
  create_directory_for(directory, "output directory");
  // O_CLOEXEC: a program this one starts does not hold the lock after it ends.
  descriptor_ = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor_ < 0) {
    throw UserError("cannot open output directory " + directory.string() + ": " + std::strerror(errno));
  }
  if (::flock(descriptor_, LOCK_EX | LOCK_NB) == 0) return;
  const int error = errno;
  ::close(descriptor_);
  if (error == EWOULDBLOCK) {
    throw UserError("output directory " + directory.string() + " is in use by another " + command +
                    ": wait for it to end, or give another directory");
  }
  throw UserError("cannot lock output directory " + directory.string() + ": " + std::strerror(error));
}

DirectoryLock::~DirectoryLock() {
  // A command refused before it wrote anything leaves no folder it made
  // (rmdir takes only an empty one: a set put in its place stays).
  if (created_) ::rmdir(directory_.c_str());
  ::close(descriptor_);
}

}  // namespace meshparticles
