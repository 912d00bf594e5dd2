#include "batch/batch_plan.hpp"

#include <iostream>

#include "batch/output_names.hpp"
#include "common/atomic_file.hpp"
#include "common/temporary_names.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

BatchPlan plan_batch(const BatchRequest& request, bool lock_out) {
  BatchPlan plan;
  plan.request = request;
  plan.request.run.quiet = true;  // one line per mesh instead of each run's progress lines
  std::vector<std::string> notes;
  std::vector<MeshInput> meshes = expand_batch_inputs(request.inputs, notes);
  if (!request.quiet) {
    for (const std::string& note : notes) std::cerr << "meshparticles: note: " << note << "\n";
  }
  if (meshes.empty()) throw UserError("no mesh to run: give mesh files, folders or .txt lists of meshes");
  const std::vector<std::string> names = output_names(meshes);
  for (std::size_t i = 0; i < meshes.size(); ++i) plan.items.push_back({std::move(meshes[i]), names[i]});
  create_directory_for(request.out, "output directory");
  if (lock_out) {
    plan.out_lock = std::make_shared<const DirectoryLock>(request.out, "batch");
    // What a killed batch left while writing (a mesh's .NAME.tmp-… set, a
    // summary's temporary), whatever host, container or process it ran in:
    // the lock proves it is gone, and no rank writes before this one plans.
    remove_stale_temporaries(request.out, Writers::none);
  }
  check_writable_directory(request.out);
  return plan;
}

std::filesystem::path output_directory(const BatchPlan& plan, std::size_t index) {
  return plan.request.out / plan.items[index].output_name;
}

}  // namespace meshparticles
