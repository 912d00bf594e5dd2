#include "common/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "common/user_error.hpp"

namespace meshparticles {

InputFile::InputFile(const std::filesystem::path& file, const std::string& label, const std::string& what)
    : label_(label) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer. The type is then
  // checked on what was opened, so the file cannot be swapped in between.
  descriptor_ = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor_ < 0) {
    if (errno == ENOENT || errno == ENOTDIR) throw UserError(label + ": no such file");
    if (errno == EACCES) throw UserError(label + ": cannot be read (permission denied)");
    if (errno == ENAMETOOLONG) throw UserError(label + ": the path is too long for this system");
    throw UserError(label + ": cannot be opened (" + std::generic_category().message(errno) + ")");
  }
  struct stat status {};
  const bool known = ::fstat(descriptor_, &status) == 0;
  std::string refusal;
  if (!known) refusal = label + ": cannot be read";
  else if (S_ISDIR(status.st_mode)) refusal = label + ": is a directory, not a " + what;
  else if (!S_ISREG(status.st_mode)) {
    refusal = label + ": not a regular file (a device, FIFO or socket), refused: reading it might never end";
  }
  if (!refusal.empty()) {
    ::close(descriptor_);
    throw UserError(refusal);
  }
  // Back to blocking reads: on a regular file O_NONBLOCK changes nothing,
  // but no reader should have to think about it.
  ::fcntl(descriptor_, F_SETFL, ::fcntl(descriptor_, F_GETFL) & ~O_NONBLOCK);
  size_ = std::uint64_t(status.st_size);
}

InputFile::~InputFile() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

std::size_t InputFile::read(char* into, std::size_t count) {
  for (;;) {
    const ssize_t got = ::read(descriptor_, into, count);
    if (got >= 0) return std::size_t(got);
    if (errno == EINTR) continue;
    throw UserError(label_ + ": read error (" + std::generic_category().message(errno) + ")");
  }
}

std::vector<char> InputFile::read_all() {
  std::vector<char> bytes(size_);
  std::size_t done = 0;
  while (done < bytes.size()) {  // a file that shrinks meanwhile ends the loop at its end
    const std::size_t got = read(bytes.data() + done, bytes.size() - done);
    if (got == 0) break;
    done += got;
  }
  bytes.resize(done);
  return bytes;
}

std::vector<char> read_input_file(const std::filesystem::path& file, const std::string& label, std::size_t max_bytes,
                                  const std::string& what) {
  InputFile input(file, label, what);
  if (input.size() > max_bytes) {
    throw UserError(label + ": " + std::to_string(input.size()) + " bytes, more than the " +
                    std::to_string(max_bytes) + " bytes a " + what + " may have");
  }
  return input.read_all();
}

std::string read_input_text(const std::filesystem::path& file, const std::string& label, const std::string& what,
                            std::size_t max_bytes) {
  const std::vector<char> bytes = read_input_file(file, label, max_bytes, what);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace meshparticles
