#pragma once
// An output directory held by one command at a time: an exclusive flock(2)
// on the directory itself while the lock lives. Two runs into one --out
// would otherwise each write part of the output set, leaving one that is
// neither run's. The kernel drops the lock when its process dies, so a
// killed run leaves nothing stale behind, and the directory holds no extra file.
#include <filesystem>
#include <string>

namespace meshparticles {

class DirectoryLock {
 public:
  // Creates `directory` if needed and locks it. Throws UserError when
  // another process holds it, naming `command` (the one that wants it).
  // A directory it created is removed when the lock ends if it is still
  // empty (the command was refused before it wrote anything).
  DirectoryLock(const std::filesystem::path& directory, const std::string& command);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  std::filesystem::path directory_;
  bool created_ = false;
  int descriptor_ = -1;
};

}  // namespace meshparticles
