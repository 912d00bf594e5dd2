#pragma once
// Reading a mesh file into memory through common/input_file (which refuses
// FIFOs, devices and directories), under a limit of its own.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "common/input_file.hpp"

namespace meshparticles {

// 2 GiB: a binary STL of 40 million triangles, far beyond any mesh whose
// distance table fits in memory, and a bound on what a hostile file can cost.
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t(2) << 30;

// The whole file; throws UserError("LABEL: problem").
inline std::vector<char> read_mesh_file(const std::filesystem::path& file, const std::string& label,
                                        std::size_t max_bytes = kMaxMeshFileBytes) {
  return read_input_file(file, label, max_bytes, "mesh file");
}

}  // namespace meshparticles
