#pragma once
// Writes that never leave half a file behind: data goes to a temporary file in
// the destination's directory, which is renamed over the destination only once
// it is complete and flushed. A crash leaves at most a stray temporary file.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace meshparticles {

// Calls write(stream) on a temporary sibling of `destination`, then renames it
// into place. Throws UserError naming the file if it cannot be written.
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// Throws UserError unless `destination` could be written later: its
// directory exists and is writable, and it is not itself a directory. Lets a
// long job fail at once instead of after the work.
void check_writable(const std::filesystem::path& destination);

// A temporary sibling path of `destination` that keeps its extension (some
// writers, OpenMesh's among them, choose the format by extension).
std::filesystem::path temporary_sibling(const std::filesystem::path& destination);

// Renames `temporary` onto `destination`, removing `temporary` on failure.
void commit_temporary(const std::filesystem::path& temporary,
                      const std::filesystem::path& destination);

}  // namespace meshparticles
