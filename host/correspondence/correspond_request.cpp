#include "correspondence/correspond_request.hpp"

#include <system_error>

#include "common/version.hpp"

namespace meshparticles {

namespace {

// The params the shape model alone reads, made after the checkpoint's last stage.
constexpr const char* kModelOnlyParams[] = {"scale", "samples"};

}  // namespace

nlohmann::json correspond_params(const CorrespondRequest& request) {
  return {{"particles", request.particles},
          {"seed", request.seed},
          {"scale", request.scale},
          {"samples", request.samples},
          {"deformation", deformation_name(request.deformation)},
          {"refine_iterations", request.refinement.iterations},
          {"correspondence_weight", request.refinement.correspondence_weight},
          {"packing", request.refinement.pack},
          {"packing_hold", request.refinement.packing_hold},
          {"even_enough", request.refinement.even_enough}};
}

nlohmann::json checkpoint_fingerprint(const CorrespondRequest& request, const std::vector<std::string>& meshes) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const std::string& name : meshes) {
    std::error_code error;
    const auto size = std::filesystem::file_size(name, error);
    const auto time = std::filesystem::last_write_time(name, error).time_since_epoch().count();
    inputs.push_back({name, error ? 0 : size, error ? 0 : time});
  }
  nlohmann::json fingerprint = correspond_params(request);
  for (const char* name : kModelOnlyParams) fingerprint.erase(name);
  fingerprint["version"] = program_version();
  // The entries' layout: a checkpoint of an earlier one (each shape's entry
  // without its mesh) is of another request, and the run starts anew.
  fingerprint["layout"] = 2;
  fingerprint["inputs"] = inputs;
  return fingerprint;
}

}  // namespace meshparticles
