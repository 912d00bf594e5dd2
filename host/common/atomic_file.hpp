#pragma once
// Writes that never leave half a file behind: data goes to a temporary file in
// the destination's directory, which is flushed, closed, synced to disk and
// only then renamed over the destination. Any failure removes the temporary
// and leaves the destination as it was; a killed process leaves a temporary
// that the next write into that directory removes (common/temporary_names.hpp).
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace meshparticles {

// Calls write(stream) on a temporary sibling of `destination`, then renames it
// into place. Throws UserError naming the file and the system's reason if it
// cannot be written (a full disk included).
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// Writes `file` directly (it must not exist yet), flushed and synced; for
// files inside a directory that is itself written atomically. Throws UserError.
void write_new_file(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write,
                    bool binary = false);

// Throws UserError unless `destination` can be written later: its directory
// exists and a file can be created there (tried, then removed), and it is
// not itself a directory. Lets a long job fail at once instead of after the work.
void check_writable(const std::filesystem::path& destination);

// Throws UserError unless a file can be created in `directory` (tried,
// then removed): the check behind check_writable.
void check_writable_directory(const std::filesystem::path& directory);

// Creates `directory` and its parents if needed; throws UserError naming
// `what` ("output directory") and the system's reason when it cannot.
void create_directory_for(const std::filesystem::path& directory, const std::string& what);

// fsync of a file or a directory (a rename is durable once its directory is synced).
void sync_to_disk(const std::filesystem::path& path);

}  // namespace meshparticles
