#pragma once
// A set of files that is replaced as a whole: written into a fresh hidden
// sibling directory, each file synced, then swapped with the destination in
// one step (renameat2 RENAME_EXCHANGE), and the previous set removed. A
// reader sees the complete old set or the complete new one, never a mix;
// a failure or a kill at any point leaves the previous set in place, and the
// next write beside it removes what the killed one left (temporary_names.hpp).
// Where the file system cannot exchange, two renames replace it: a reader
// may then briefly find no directory, never a mixed one, and a kill between
// them is undone by the next write.
#include <filesystem>
#include <functional>
#include <set>
#include <string>

namespace meshparticles {

// Throws UserError unless `directory` can later be replaced by a set of
// `names`: its parent exists (created if needed) and takes new entries, and
// the directory, if present, is a directory holding nothing but `names`
// (what would be lost otherwise is named; nothing else is ever deleted).
void check_replaceable_directory(const std::filesystem::path& directory, const std::set<std::string>& names);

// For a `directory` about to be locked (common/directory_lock) and then
// replaced as a whole: where it is missing because a swap without exchange
// was killed between its two renames, puts back the previous set that swap
// retired (.NAME.old-HOST-PID-N beside it), whoever retired it. Best effort.
void restore_retired_directory(const std::filesystem::path& directory);

// For a `directory` this process now holds locked, before it writes
// anything there: removes what a killed replacement of it left beside it
// (its staging set, or the previous set it retired), whoever made them -
// the lock proves that no writer of it is alive (common/temporary_names.hpp).
void remove_leftovers_beside(const std::filesystem::path& directory);

// Calls fill(staging) to write every file into an empty staging directory
// (with write_new_file), then puts it in place of `directory`.
void write_directory_atomically(const std::filesystem::path& directory, const std::set<std::string>& names,
                                const std::function<void(const std::filesystem::path& staging)>& fill);

}  // namespace meshparticles
