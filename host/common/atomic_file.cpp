#include "common/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/user_error.hpp"

namespace meshparticles {

std::filesystem::path temporary_sibling(const std::filesystem::path& destination) {
  static std::atomic<unsigned> counter{0};
  // Hidden, unique per process and call, same extension as the destination.
  std::string name = ".";
  name += destination.stem().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  name += destination.extension().string();
  return destination.parent_path() / name;
}

void commit_temporary(const std::filesystem::path& temporary,
                      const std::filesystem::path& destination) {
  std::error_code error;
  std::filesystem::rename(temporary, destination, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw UserError(destination.string() + ": cannot write: " + error.message());
  }
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
  if (::access(directory.c_str(), W_OK) != 0) {
    throw UserError(destination.string() + ": cannot write: permission denied");
  }
}

void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(std::ostream&)>& write, bool binary) {
  const auto temporary = temporary_sibling(destination);
  {
    std::ofstream out(temporary, binary ? std::ios::binary : std::ios::out);
    if (!out) {
      throw UserError(destination.string() + ": cannot write: " + std::strerror(errno));
    }
    try {
      write(out);
    } catch (...) {
      out.close();
      std::filesystem::remove(temporary);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(temporary);
      throw UserError(destination.string() + ": cannot write (disk full?)");
    }
  }
  commit_temporary(temporary, destination);
}

}  // namespace meshparticles
