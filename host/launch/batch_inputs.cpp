#include "launch/batch_inputs.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "common/input_file.hpp"
#include "common/user_error.hpp"
#include "mesh/io/mesh_reader.hpp"

namespace meshparticles {

namespace {

bool has_mesh_extension(const std::filesystem::path& file) {
  try {
    mesh_format_of(file);
    return true;
  } catch (const UserError&) {
    return false;
  }
}

bool is_list_file(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension == ".txt";
}

std::vector<std::filesystem::path> meshes_in_folder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> meshes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && has_mesh_extension(entry.path())) meshes.push_back(entry.path());
  }
  if (error) throw UserError("cannot read folder " + folder.string() + ": " + error.message());
  if (meshes.empty()) throw UserError("folder " + folder.string() + " holds no mesh file (" + mesh_extensions() + ")");
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::filesystem::path> meshes_in_list(const std::filesystem::path& list) {
  std::istringstream in(read_input_text(list, "mesh list " + list.string(), "mesh list"));
  std::vector<std::filesystem::path> meshes;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string entry = trimmed(line);
    if (entry.empty() || entry.front() == '#') continue;
    const std::filesystem::path mesh = list.parent_path() / entry;
    if (!has_mesh_extension(mesh)) {
      throw UserError(list.string() + ": line " + std::to_string(number) + ": '" + entry +
                      "' is not a mesh file (" + mesh_extensions() + ")");
    }
    meshes.push_back(mesh.lexically_normal());
  }
  if (meshes.empty()) throw UserError("mesh list " + list.string() + " names no mesh");
  return meshes;
}

std::vector<std::filesystem::path> meshes_of(const std::string& input) {
  const std::filesystem::path path(input);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return meshes_in_folder(path);
  if (is_list_file(path)) return meshes_in_list(path);
  return {path};
}

}  // namespace

std::vector<MeshInput> expand_batch_inputs(const std::vector<std::string>& inputs, std::vector<std::string>& notes) {
  std::vector<MeshInput> meshes;
  std::map<std::filesystem::path, std::filesystem::path> first_seen;  // resolved -> as given
  for (const std::string& input : inputs) {
    for (const std::filesystem::path& path : meshes_of(input)) {
      std::error_code error;
      MeshInput mesh{path, std::filesystem::weakly_canonical(std::filesystem::absolute(path), error), 0};
      if (error) mesh.resolved = std::filesystem::absolute(path).lexically_normal();
      const auto [seen, fresh] = first_seen.emplace(mesh.resolved, path);
      if (!fresh) {
        notes.push_back(path.string() + " is the same file as " + seen->second.string() + ": run once");
        continue;
      }
      const std::uintmax_t bytes = std::filesystem::file_size(path, error);
      mesh.bytes = error ? 0 : bytes;
      meshes.push_back(std::move(mesh));
    }
  }
  return meshes;
}

}  // namespace meshparticles
