#pragma once
// What `correspond` is asked, and its one description: summary.json's
// params and the checkpoint's fingerprint are both made from
// `correspond_params`, so a parameter added there cannot be left out of
// the fingerprint (a stale checkpoint would resume silently).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "correspondence/joint_refinement.hpp"
#include "correspondence/template_deformation.hpp"

namespace meshparticles {

struct CorrespondRequest {
  // Mesh files, folders of meshes, .txt files listing meshes
  // (launch/batch_inputs); the first mesh is the template.
  std::vector<std::string> inputs;
  std::filesystem::path out;
  std::size_t particles = 256;
  std::uint64_t seed = 1;  // the template's start and the model's draws
  JointRefinementOptions refinement;
  TemplateDeformation deformation = TemplateDeformation::graph;  // the template onto each shape
  bool scale = true;           // the model's alignment scales the shapes
  std::size_t samples = 1000;  // the model's shapes drawn per number of modes
  unsigned threads = 0;        // per process (0: the cores, shared among a node's ranks)
  bool quiet = false;
};

// Every parameter that changes a result, by its name in summary.json's params.
nlohmann::json correspond_params(const CorrespondRequest& request);

// What the checkpoint's stages depend on: the params less those only the
// model reads, the version, and each input mesh's path, size and time (a run
// of other inputs does not resume this one's).
nlohmann::json checkpoint_fingerprint(const CorrespondRequest& request, const std::vector<std::string>& meshes);

}  // namespace meshparticles
