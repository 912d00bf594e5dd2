#pragma once
// The names of our temporary files and directories, and the clean-up of the
// ones a killed process left behind. A temporary sits beside what it will
// become, hidden, and says who made it:
//   .report.tmp-HOST-PID-N.json      a file being written (keeps the extension)
//   .out.tmp-HOST-PID-N              an output set being written
//   .out.old-HOST-PID-N              the previous output set being retired
// A process can only be asked whether it lives on this host, so in a
// directory anyone may write, only temporaries of this host whose process is
// gone are stale; those of a living process, or of another host sharing the
// directory, are left alone. In a directory the caller holds locked
// (common/directory_lock: batch's and correspond's --out), the lock proves
// that no writer of it is alive, so every temporary there is stale, whatever
// host, container or PID namespace made it.
#include <filesystem>
#include <string>

namespace meshparticles {

enum class TemporaryKind { staging, retired };

// Who may still be writing the temporaries of a directory: anyone (only
// those of this host's gone processes are stale), or no one (the caller
// holds the directory's lock and has written nothing there yet).
enum class Writers { anyone, none };

// A fresh name beside `destination` (unique per process and call).
std::filesystem::path temporary_sibling(const std::filesystem::path& destination,
                                        TemporaryKind kind = TemporaryKind::staging);

// Removes the stale temporaries in `directory` (with `destination`, only
// those of the output set of that name); a stale retired output set whose
// destination is missing (killed between the two renames of a swap) is put
// back instead. Errors are ignored: clean-up is best effort and must not
// stop the work.
void remove_stale_temporaries(const std::filesystem::path& directory, Writers writers = Writers::anyone,
                              const std::string& destination = "");

}  // namespace meshparticles
