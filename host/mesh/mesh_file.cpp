#include "mesh/mesh_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "common/user_error.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

// Closes the descriptor however the read ends.
class OpenFile {
 public:
  explicit OpenFile(int descriptor) : descriptor_(descriptor) {}
  ~OpenFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int get() const { return descriptor_; }

 private:
  int descriptor_;
};

}  // namespace

std::vector<char> read_mesh_file(const std::filesystem::path& file, const std::string& label, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer. The type is then
  // checked on what was opened, so the file cannot be swapped in between.
  const OpenFile input(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (input.get() < 0) {
    if (errno == ENOENT || errno == ENOTDIR) throw UserError(label + ": no such file");
    if (errno == EACCES) throw UserError(label + ": cannot be read (permission denied)");
    throw UserError(label + ": cannot be opened (" + std::generic_category().message(errno) + ")");
  }
  struct stat status {};
  if (::fstat(input.get(), &status) != 0) throw UserError(label + ": cannot be read");
  if (S_ISDIR(status.st_mode)) throw UserError(label + ": is a directory, not a mesh file");
  if (!S_ISREG(status.st_mode)) {
    throw UserError(label + ": not a regular file (a device, FIFO or socket), refused: reading it might never end");
  }
  const auto size = static_cast<std::size_t>(status.st_size);
  if (size > max_bytes) {
    throw UserError(label + ": " + plural(size, "byte") + ", more than the " + plural(max_bytes, "byte") +
                    " a mesh file may have");
  }
  std::vector<char> bytes(size);
  std::size_t done = 0;
  while (done < size) {  // a file that shrinks meanwhile ends the loop at its end
    const ssize_t got = ::read(input.get(), bytes.data() + done, size - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw UserError(label + ": read error (" + std::generic_category().message(errno) + ")");
    if (got == 0) break;
    done += std::size_t(got);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace meshparticles
