#pragma once
// Reading a mesh file into memory, refusing what a reader must not touch:
// anything but a regular file (a FIFO or a device such as /dev/urandom could
// block or never end) and files over kMaxMeshFileBytes.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace meshparticles {

// 2 GiB: a binary STL of 40 million triangles, far beyond any mesh whose
// distance table fits in memory, and a bound on what a hostile file can cost.
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t(2) << 30;

// The whole file; throws UserError("LABEL: problem").
std::vector<char> read_mesh_file(const std::filesystem::path& file, const std::string& label,
                                 std::size_t max_bytes = kMaxMeshFileBytes);

}  // namespace meshparticles
