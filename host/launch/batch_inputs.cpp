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

// A folder's mesh files. An entry named as a mesh whose file cannot be
// reached (a symlink loop, a link to nothing) is named in `notes` and
// skipped: the others run (the error of one entry once stopped the whole
// listing, or was dropped without a word).
std::vector<std::filesystem::path> meshes_in_folder(const std::filesystem::path& folder,
                                                    std::vector<std::string>& notes) {
  std::vector<std::filesystem::path> meshes;
  std::vector<std::string> skipped;
  std::error_code error;
  for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error)) {
    if (!has_mesh_extension(entry->path())) continue;
    std::error_code unreachable;
    const std::filesystem::file_status status = entry->status(unreachable);
    if (unreachable == std::errc::no_such_file_or_directory || status.type() == std::filesystem::file_type::not_found) {
      skipped.push_back(entry->path().string() + ": a link to nothing: skipped");
    } else if (unreachable) {
      skipped.push_back(entry->path().string() + ": cannot read it (" + unreachable.message() + "): skipped");
    } else if (std::filesystem::is_regular_file(status)) {
      meshes.push_back(entry->path());
    }
  }
  if (error) throw UserError("cannot read folder " + folder.string() + ": " + error.message());
  std::sort(skipped.begin(), skipped.end());
  if (meshes.empty()) {
    std::string why;
    for (const std::string& note : skipped) why += "; " + note;
    throw UserError("folder " + folder.string() + " holds no mesh file (" + mesh_extensions() + ")" + why);
  }
  notes.insert(notes.end(), skipped.begin(), skipped.end());
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

std::vector<std::filesystem::path> meshes_of(const std::string& input, std::vector<std::string>& notes) {
  const std::filesystem::path path(input);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return meshes_in_folder(path, notes);
  if (is_list_file(path)) return meshes_in_list(path);
  return {path};
}

}  // namespace

std::vector<MeshInput> expand_batch_inputs(const std::vector<std::string>& inputs, std::vector<std::string>& notes) {
  std::vector<MeshInput> meshes;
  std::map<std::filesystem::path, std::filesystem::path> first_seen;  // resolved -> as given
  for (const std::string& input : inputs) {
    for (const std::filesystem::path& path : meshes_of(input, notes)) {
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
