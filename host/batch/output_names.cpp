#include "batch/output_names.hpp"

#include <algorithm>
#include <map>

#include "common/user_error.hpp"
#include "reports/file_digest.hpp"

namespace meshparticles {

namespace {

std::string plain_name(const std::filesystem::path& file) {
  std::string name = file.stem().string();
  for (char& c : name) {
    const bool kept = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
    if (!kept) c = '_';
  }
  if (name.empty()) return "mesh";
  if (name.front() == '.') name.front() = '_';  // hidden names are our temporaries'
  return name;
}

}  // namespace

std::vector<std::string> output_names(const std::vector<MeshInput>& meshes) {
  std::vector<std::string> names;
  std::map<std::string, std::size_t> uses;
  for (const std::string& reserved : kBatchFileNames) uses[reserved] = 1;
  for (const MeshInput& mesh : meshes) ++uses[names.emplace_back(plain_name(mesh.path))];
  std::map<std::string, const MeshInput*> owner;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    if (uses[names[i]] > 1) names[i].append("+").append(text_sha256(meshes[i].resolved.string()), 0, 8);
    const auto [other, fresh] = owner.emplace(names[i], &meshes[i]);
    if (!fresh) {
      throw UserError(meshes[i].path.string() + " and " + other->second->path.string() + " would share output " +
                      names[i] + ": rename one of them");
    }
  }
  return names;
}

}  // namespace meshparticles
