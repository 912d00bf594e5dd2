#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/temporary_names.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

std::string system_reason(int error) { return std::strerror(error); }

// Removes the temporary on every way out but a successful commit.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    std::error_code ignored;
    if (!committed_) std::filesystem::remove(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  void commit(const std::filesystem::path& destination) {
    std::error_code error;
    std::filesystem::rename(path_, destination, error);
    if (error) throw UserError(destination.string() + ": cannot write: " + error.message());
    committed_ = true;
  }

 private:
  std::filesystem::path path_;
  bool committed_ = false;
};

// The stream's data written, flushed and closed, or a UserError naming
// `destination` and the reason (errno is what the failing write or close left).
void write_and_close(const std::filesystem::path& file, const std::filesystem::path& destination,
                     const std::function<void(std::ostream&)>& write, bool binary) {
  std::ofstream out(file, binary ? std::ios::binary | std::ios::trunc : std::ios::out | std::ios::trunc);
  if (!out) throw UserError(destination.string() + ": cannot write: " + system_reason(errno));
  errno = 0;
  write(out);
  out.close();
  if (!out) {
    throw UserError(destination.string() + ": cannot write: " +
                    (errno ? system_reason(errno) : std::string("the write failed (disk full?)")));
  }
}

}  // namespace

void sync_to_disk(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw UserError(path.string() + ": cannot sync to disk: " + system_reason(errno));
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: this file system cannot sync
  const int sync_error = errno;
  ::close(fd);
  if (!synced) throw UserError(path.string() + ": cannot write: " + system_reason(sync_error));
}

void create_directory_for(const std::filesystem::path& directory, const std::string& what) {
  if (directory.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UserError("cannot create " + what + " " + directory.string() + ": " + error.message());
  if (!std::filesystem::is_directory(directory, error)) {
    throw UserError("cannot create " + what + " " + directory.string() + ": a file of that name exists");
  }
}

void check_writable_directory(const std::filesystem::path& directory) {
  // access() says yes to root everywhere, and nothing about read-only file
  // systems or /proc: only creating a file tells.
  const std::filesystem::path probe = temporary_sibling(directory / "write-probe");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw UserError("cannot write to " + directory.string() + ": " + system_reason(errno));
  ::close(fd);
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

void check_writable(const std::filesystem::path& destination) {
  const std::filesystem::path directory = destination.parent_path().empty() ? "." : destination.parent_path();
  std::error_code error;
  if (std::filesystem::is_directory(destination, error)) {
    throw UserError(destination.string() + ": cannot write: it is a directory");
  }
  if (!std::filesystem::is_directory(directory, error)) {
    throw UserError(destination.string() + ": cannot write: no directory " + directory.string());
  }
  try {
    check_writable_directory(directory);
  } catch (const UserError& refusal) {
    throw UserError(destination.string() + ": " + refusal.what());
  }
}

void write_new_file(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write,
                    bool binary) {
  write_and_close(file, file, write, binary);
  sync_to_disk(file);
}

void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(std::ostream&)>& write, bool binary) {
  std::error_code error;
  if (std::filesystem::is_directory(destination, error)) {
    throw UserError(destination.string() + ": cannot write: it is a directory");
  }
  remove_stale_temporaries(destination.parent_path());
  TemporaryFile temporary(temporary_sibling(destination));
  write_and_close(temporary.path(), destination, write, binary);
  sync_to_disk(temporary.path());
  temporary.commit(destination);
  sync_to_disk(destination.parent_path().empty() ? "." : destination.parent_path());
}

}  // namespace meshparticles
