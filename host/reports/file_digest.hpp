#pragma once
// The SHA-256 of a file's bytes, as `sha256sum` prints it: report.json
// records it for the mesh a run read, so a resumed batch can tell that a
// mesh file is the one its output was computed from (and anyone can check
// which file produced a result).
#include <filesystem>
#include <span>
#include <string>

namespace meshparticles {

// 64 lowercase hex digits. Throws UserError naming the file and the
// system's reason when it cannot be read.
std::string file_sha256(const std::filesystem::path& file);

// The same digest of a text in memory.
std::string text_sha256(const std::string& text);
// The same digest of bytes in memory (a mesh file as it was read).
std::string bytes_sha256(std::span<const char> bytes);

}  // namespace meshparticles
