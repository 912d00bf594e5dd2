#include "common/atomic_directory.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "common/atomic_file.hpp"
#include "common/temporary_names.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// `directory` with a symbolic link at its end followed: the link stays, the
// set behind it is replaced. Relative paths stay as given.
std::filesystem::path resolved(const std::filesystem::path& directory) {
  std::error_code error;
  const std::filesystem::path plain = directory.lexically_normal();
  if (std::filesystem::is_symlink(plain, error)) return std::filesystem::canonical(plain, error);
  return plain.filename().empty() ? plain.parent_path() : plain;  // "out/" -> "out"
}

std::filesystem::path parent_of(const std::filesystem::path& directory) {
  return directory.parent_path().empty() ? std::filesystem::path(".") : directory.parent_path();
}

// Removes a staging directory on every way out but a successful swap.
class StagingDirectory {
 public:
  explicit StagingDirectory(std::filesystem::path path) : path_(std::move(path)) {
    if (::mkdir(path_.c_str(), 0777) != 0) {
      throw UserError("cannot write to " + path_.parent_path().string() + ": " + std::strerror(errno));
    }
  }
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;
  ~StagingDirectory() {
    std::error_code ignored;
    if (!placed_) std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  void placed() { placed_ = true; }

 private:
  std::filesystem::path path_;
  bool placed_ = false;
};

// Puts `staging` where `directory` is (or is not yet). Returns the path the
// previous set now has, or an empty path when there was none.
std::filesystem::path swap_into_place(const std::filesystem::path& staging, const std::filesystem::path& directory) {
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_NOREPLACE) == 0) return {};
  const int no_replace_error = errno;
  if (no_replace_error == EEXIST &&
      ::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_EXCHANGE) == 0) {
    return staging;  // the old set now has the staging name
  }
  if (no_replace_error != EEXIST && no_replace_error != EINVAL && no_replace_error != ENOSYS) {
    throw UserError("cannot write output directory " + directory.string() + ": " + std::strerror(no_replace_error));
  }
  // No exchange on this file system: retire the old set under a name the next
  // write restores if this process dies before the second rename.
  std::error_code error;
  std::filesystem::path retired;
  if (std::filesystem::exists(directory, error)) {
    retired = temporary_sibling(directory, TemporaryKind::retired);
    std::filesystem::rename(directory, retired, error);
    if (error) throw UserError("cannot replace output directory " + directory.string() + ": " + error.message());
  }
  std::filesystem::rename(staging, directory, error);
  if (error) {
    std::error_code ignored;
    if (!retired.empty()) std::filesystem::rename(retired, directory, ignored);
    throw UserError("cannot write output directory " + directory.string() + ": " + error.message());
  }
  return retired;
}

}  // namespace

void check_replaceable_directory(const std::filesystem::path& given, const std::set<std::string>& names) {
  const std::filesystem::path directory = resolved(given);
  if (directory.empty() || directory == directory.root_path() || directory.filename() == "." ||
      directory.filename() == "..") {
    throw UserError("output directory " + given.string() + ": give a directory of its own, not " + directory.string());
  }
  std::error_code error;
  const auto status = std::filesystem::status(directory, error);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status)) {
      throw UserError("cannot write output directory " + given.string() + ": a file of that name exists");
    }
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
      const std::string name = entry.path().filename().string();
      if (!names.count(name)) {
        throw UserError("output directory " + given.string() + " holds " + name +
                        ", which a run did not write; it would be lost: give a new or empty directory");
      }
    }
    if (error) throw UserError("cannot read output directory " + given.string() + ": " + error.message());
  }
  create_directory_for(parent_of(directory), "the parent of output directory");
  struct stat own {}, parent {};
  if (::stat(directory.c_str(), &own) == 0 && ::stat(parent_of(directory).c_str(), &parent) == 0 &&
      own.st_dev != parent.st_dev) {
    throw UserError("output directory " + given.string() + " is a mount point, which cannot be replaced: give a "
                    "directory inside it");
  }
  check_writable_directory(parent_of(directory));
}

void restore_retired_directory(const std::filesystem::path& given) {
  const std::filesystem::path directory = resolved(given);
  std::error_code error;
  if (directory.filename().empty() || std::filesystem::exists(std::filesystem::symlink_status(directory, error))) {
    return;
  }
  std::string prefix = ".";
  prefix += directory.filename().string();
  prefix += ".old-";
  for (const auto& entry : std::filesystem::directory_iterator(parent_of(directory), error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix) || !entry.is_directory(error)) continue;
    // NOREPLACE: a directory made meanwhile (a run beside this one) is not replaced.
    if (::renameat2(AT_FDCWD, entry.path().c_str(), AT_FDCWD, directory.c_str(), RENAME_NOREPLACE) == 0) return;
    if (errno == EINVAL || errno == ENOSYS) {  // no flags on this file system (NFS): a plain rename
      std::filesystem::rename(entry.path(), directory, error);
    }
    return;
  }
}

void remove_leftovers_beside(const std::filesystem::path& given) {
  const std::filesystem::path directory = resolved(given);
  remove_stale_temporaries(parent_of(directory), Writers::none, directory.filename().string());
}

void write_directory_atomically(const std::filesystem::path& given, const std::set<std::string>& names,
                                const std::function<void(const std::filesystem::path& staging)>& fill) {
  const std::filesystem::path directory = resolved(given);
  check_replaceable_directory(directory, names);
  remove_stale_temporaries(parent_of(directory));
  StagingDirectory staging(temporary_sibling(directory));
  fill(staging.path());
  sync_to_disk(staging.path());
  const std::filesystem::path previous = swap_into_place(staging.path(), directory);
  staging.placed();
  sync_to_disk(parent_of(directory));
  std::error_code ignored;
  if (!previous.empty()) std::filesystem::remove_all(previous, ignored);
}

}  // namespace meshparticles
